#include "devices/profiles/dsp408/pid_controller.h"

#include <algorithm>
#include <cmath>

namespace dsp408 {

void PidController::reset() {
  i_ = 0;
  last_e_ = 0;
  last_w_ = 0;
  primed_ = false;
}

double PidController::update(double e, double w, double dt) {
  const bool pos = e >= 0;
  const double kp = pos ? p_.kp_pos : p_.kp_neg;
  const double ki = pos ? p_.ki_pos : p_.ki_neg;
  const double kd = pos ? p_.kd_pos : p_.kd_neg;
  const double outside = pos ? p_.i_window_outside_pos : p_.i_window_outside_neg;
  const double inside = pos ? p_.i_window_inside_pos : p_.i_window_inside_neg;
  const double mag = std::abs(e);
  if (ki <= 0) {
    i_ = 0;
  } else if (outside > 0 && mag >= outside) {
    if (!p_.hold_i_outside) i_ = 0;
  } else if (!(inside > 0 && mag <= inside)) {
    i_ = std::clamp(i_ + ki * e * dt, p_.out_min, p_.out_max);
  }
  double d = 0, dw = 0;
  if (primed_ && dt > 0) {
    d = (e - last_e_) / dt;
    dw = (w - last_w_) / dt;
  }
  last_e_ = e;
  last_w_ = w;
  primed_ = true;
  const double u = kp * e + i_ + kd * d + p_.ff_w * w + p_.ff_dw * dw;
  return std::clamp(u, p_.out_min, p_.out_max);
}

}  // namespace dsp408
