#include "devices/vtvpcd/pump_controller.h"

#include <algorithm>

#include "devices/vtvpcd/power_limiter.h"

namespace vtvpcd {

PumpController::PumpController(const Settings& settings) : s_(settings), limits_(limits_of(settings.pump_type)) {
  reset();
}

void PumpController::reset() {
  angle_ramp_.reset(0.0);
  pressure_ramp_.reset(0.0);
  pressure_.reset(limits_.alpha_lo);
  was_energised_ = false;
  out_ = ControlOutputs{};
  out_.spool_command = s_.x_off_pct;
}

double PumpController::controlled_pressure(double alpha_r, double p_a, double p_b) const {
  // A31: configurable; by default the side the flow goes to (A4VSO/A2V: port B; A4VSG: B for a
  // positive angle command, A for a negative one).
  switch (s_.controlled_pressure) {
    case ControlledPressure::A: return p_a;
    case ControlledPressure::B: return p_b;
    case ControlledPressure::Max: return std::max(p_a, p_b);
    case ControlledPressure::FlowSide: break;
  }
  if (s_.pump_type == PumpType::A4VSG && alpha_r < 0.0) return p_a;
  return p_b;
}

const ControlOutputs& PumpController::cycle(const Inputs& in, double dt_s) {
  const auto& c = in.cmd;
  if (in.energised && !was_energised_) {
    // Bumpless start: the ramps begin where the pump is.
    angle_ramp_.reset(std::clamp(in.alpha_meas, limits_.alpha_lo, limits_.alpha_hi));
    pressure_ramp_.reset(controlled_pressure(angle_ramp_.value(), in.p_a, in.p_b));
  }
  was_energised_ = in.energised;
  out_.energised = in.energised;

  if (in.energised) {
    out_.alpha_r = angle_ramp_.step(c.alpha_pct, c.ramp_alpha_s, 100.0, dt_s);
    out_.p_r = pressure_ramp_.step(c.pressure_bar, c.ramp_pressure_s, s_.p_ref_bar, dt_s);
  } else {
    out_.alpha_r = angle_ramp_.value();  // frozen until enabled again
    out_.p_r = pressure_ramp_.value();
  }
  out_.power_r = c.power_pct;
  out_.p_ctrl = controlled_pressure(out_.alpha_r, in.p_a, in.p_b);

  const PressureController::Params pc{c.kp, c.ti_ms, s_.p_ref_bar, limits_.alpha_lo, limits_.alpha_hi};
  if (in.energised) {
    out_.alpha_p = pressure_.update(out_.p_r, out_.p_ctrl, pc, dt_s);
  } else {
    pressure_.reset(limits_.alpha_lo);
    out_.alpha_p = pressure_.output();
  }
  out_.alpha_power = power_limit(out_.power_r, s_.p_ref_bar, out_.p_ctrl, limits_.alpha_hi);

  // Minimum selection; on the negative side of an over-centre pump the mirror image (§4.6).
  const bool negative = s_.pump_type == PumpType::A4VSG && out_.alpha_r < 0.0;
  if (!negative) {
    out_.alpha_res = std::min({out_.alpha_r, out_.alpha_p, out_.alpha_power});
    out_.branch = out_.alpha_r <= out_.alpha_p && out_.alpha_r <= out_.alpha_power ? Branch::Angle
                  : out_.alpha_p <= out_.alpha_power                              ? Branch::Pressure
                                                                                  : Branch::Power;
  } else {
    out_.alpha_res = std::max({out_.alpha_r, -out_.alpha_p, -out_.alpha_power});
    out_.branch = out_.alpha_r >= -out_.alpha_p && out_.alpha_r >= -out_.alpha_power ? Branch::Angle
                  : -out_.alpha_p >= -out_.alpha_power                               ? Branch::Pressure
                                                                                     : Branch::Power;
  }
  if (in.slave) {
    out_.alpha_res = c.slave_alpha_pct;
    out_.branch = Branch::Slave;
  }
  out_.alpha_res = std::clamp(out_.alpha_res, limits_.alpha_lo, limits_.alpha_hi);
  if (in.energised && out_.branch != Branch::Pressure) pressure_.track(negative ? -out_.alpha_res : out_.alpha_res);

  if (in.energised) {
    out_.valve_cmd = std::clamp(s_.k_pos * (out_.alpha_res - in.alpha_meas) + in.zero_valve_pct, -100.0, 100.0);
    out_.spool_command = out_.valve_cmd;
  } else {
    out_.branch = Branch::None;
    out_.valve_cmd = 0.0;
    out_.spool_command = s_.x_off_pct;  // de-energised: spring offset position of the pilot valve
  }
  return out_;
}

}  // namespace vtvpcd
