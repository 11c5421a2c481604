#include "devices/vtvpcd/pressure_controller.h"

#include <algorithm>

namespace vtvpcd {

double PressureController::update(double p_cmd_bar, double p_act_bar, const Params& p, double dt_s) {
  const double e = 100.0 * (p_cmd_bar - p_act_bar) / p.p_ref_bar;
  output_ = std::clamp(p.kp * e + integral_, p.alpha_lo, p.alpha_hi);
  // Kp = 0 freezes the controller: the output is the integrator, which no longer moves.
  integral_ = std::clamp(integral_ + p.kp * e * dt_s / (p.ti_ms / 1000.0), p.alpha_lo, p.alpha_hi);
  return output_;
}

void PressureController::track(double alpha_res) { integral_ = std::min(integral_, alpha_res); }

void PressureController::reset(double alpha_lo) {
  integral_ = alpha_lo;
  output_ = alpha_lo;
}

}  // namespace vtvpcd
