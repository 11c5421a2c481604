// A small stand-in for the plant when the node runs on its own (`vplant node --device vtvpcd`,
// setting builtin_plant = true): pilot spool as a first-order lag, swash plate integrating the
// spool opening, and one hydraulic volume on the pump's pressure port with a throttle load,
// leakage and a relief valve (digest §4.8). Enough for plausible act. Angle / act. pressure
// responses; the full pump, lines and loads live in plant/ and replace this model there
// (builtin_plant = false, ports wired by the scenario).
#pragma once

#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

class BuiltinPumpModel {
 public:
  BuiltinPumpModel(const BuiltinPlantSettings& settings, PumpType type);

  /// Advances by `dt_s` with the pilot valve commanded to `spool_command_pct` (sub-steps of at
  /// most 0.25 ms).
  void step(double spool_command_pct, double dt_s);

  double alpha_pct() const { return alpha_; }
  double spool_pct() const { return spool_; }
  double p_a_bar() const { return p_a_; }
  double p_b_bar() const { return p_b_; }
  double pressure_bar() const { return p_; }
  double flow_l_min() const;

  /// Run-time quantities (side interface): throttle load K_L (L/min/sqrt(bar), 0 = dead-headed)
  /// and shaft speed (1/min).
  double& load_coefficient() { return k_load_; }
  double& speed_rpm() { return speed_rpm_; }

 private:
  void substep(double spool_command_pct, double h);

  BuiltinPlantSettings s_;
  PumpType type_;
  double alpha_lo_, alpha_hi_;
  double k_load_, speed_rpm_;
  double alpha_ = 0, spool_ = 0, p_ = 0, p_a_ = 0, p_b_ = 0;
};

}  // namespace vtvpcd
