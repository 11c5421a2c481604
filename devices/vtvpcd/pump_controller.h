// The closed-loop control of one cycle (digest §4.3-§4.7): ramps, pressure PI, power limit, the
// minimum selection of the three swivel-angle demands (or the slave set-point), and the P-type
// swivel-angle position loop whose output is the pilot valve command. While not energised
// (Enable = 0 or a stop fault) the valve command reads 0 and the pilot valve sits in its spring
// offset position, which swivels the pump to its fail-safe end.
#pragma once

#include <cstdint>

#include "devices/vtvpcd/command_ramp.h"
#include "devices/vtvpcd/command_sources.h"
#include "devices/vtvpcd/pressure_controller.h"
#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

/// The demand that produced the resulting angle (ties: angle > pressure > power).
enum class Branch : std::uint8_t { None, Angle, Pressure, Power, Slave };

struct ControlOutputs {
  double alpha_r = 0;      ///< Angle CMD 0x2F33 (after selection and ramp), %
  double p_r = 0;          ///< Press CMD 0x2F0E, bar
  double power_r = 0;      ///< Power CMD 0x2F18, %
  double alpha_p = 0;      ///< pressure stroke 0x2F32, %
  double alpha_power = 0;  ///< power-limit demand, %
  double alpha_res = 0;    ///< res. Angle CMD 0x2F20, %
  double p_ctrl = 0;       ///< controlled pressure, bar
  double valve_cmd = 0;    ///< valve CMD 0x2F1F, % (0 while de-energised)
  double spool_command = 0;  ///< what drives the pilot valve, % (x_off while de-energised)
  Branch branch = Branch::None;
  bool energised = false;
};

class PumpController {
 public:
  explicit PumpController(const Settings& settings);

  struct Inputs {
    bool energised = false;   ///< Enable = 1 and no stop fault
    double alpha_meas = 0;    ///< act. Angle, %
    double p_a = 0, p_b = 0;  ///< bar
    SelectedCommands cmd;
    bool slave = false;
    double zero_valve_pct = 0;
  };

  const ControlOutputs& cycle(const Inputs& in, double dt_s);
  /// Power-on / reset of the amplifier card.
  void reset();
  const ControlOutputs& outputs() const { return out_; }
  const PressureController& pressure_controller() const { return pressure_; }

 private:
  double controlled_pressure(double alpha_r, double p_a, double p_b) const;

  const Settings& s_;
  PumpLimits limits_;
  CommandRamp angle_ramp_;
  CommandRamp pressure_ramp_;
  PressureController pressure_;
  bool was_energised_ = false;
  ControlOutputs out_;
};

}  // namespace vtvpcd
