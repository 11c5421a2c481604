// Control-deviation monitoring behind fault 19 "Loop Fault Stopp" (digest §4.9; only with
// monitor_enable): the swivel angle more than 10 % away from its set-point for over 1 s
// (EMCY 0x8301), or, while the pressure controller is the active branch, the pressure more than
// 10 % of p_ref away from its command for over 2 s (EMCY 0x8302).
#pragma once

#include <cmath>

#include "devices/vtvpcd/pump_controller.h"

namespace vtvpcd {

class LoopMonitor {
 public:
  static constexpr double kAngleLimitPct = 10.0, kAngleTimeS = 1.0;
  static constexpr double kPressureLimitPct = 10.0, kPressureTimeS = 2.0;

  void update(const ControlOutputs& c, double alpha_meas, double p_ref_bar, double dt_s) {
    const bool angle_off = c.energised && std::abs(c.alpha_res - alpha_meas) > kAngleLimitPct;
    const bool pressure_off = c.energised && c.branch == Branch::Pressure &&
                              std::abs(c.p_r - c.p_ctrl) > kPressureLimitPct * p_ref_bar / 100.0;
    angle_time_ = angle_off ? angle_time_ + dt_s : 0.0;
    pressure_time_ = pressure_off ? pressure_time_ + dt_s : 0.0;
  }
  bool position_fault() const { return angle_time_ > kAngleTimeS; }
  bool pressure_fault() const { return pressure_time_ > kPressureTimeS; }
  void reset() { angle_time_ = pressure_time_ = 0.0; }

 private:
  double angle_time_ = 0.0;
  double pressure_time_ = 0.0;
};

}  // namespace vtvpcd
