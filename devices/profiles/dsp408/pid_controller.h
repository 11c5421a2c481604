// Closed-loop controller of the DSP 408 valve electronics (pressure, velocity, position modes):
// PID on the normalised control deviation with separate gains for a positive and a negative
// deviation, a switched integrator (I-windows) and feed-forward of the set point and its speed.
//
//   u = kp·e + I + kd·de/dt + ff_w·w + ff_dw·dw/dt,   I += ki·e·dt   (gains picked by sign of e)
//   |e| ≥ I-window outside (if set): I is reset to 0 (or kept, `hold_i_outside`);
//   |e| ≤ I-window inside (if set):  I is kept (no further integration).
// The output and the integrator are limited to [out_min, out_max].
#pragma once

namespace dsp408 {

struct PidParameters {
  double kp_pos = 0, kp_neg = 0;  ///< proportional gain for e ≥ 0 / e < 0
  double ki_pos = 0, ki_neg = 0;  ///< 1/s; 0 = no I-part
  double kd_pos = 0, kd_neg = 0;  ///< s
  double i_window_outside_pos = 0, i_window_outside_neg = 0;  ///< normalised; 0 = off
  double i_window_inside_pos = 0, i_window_inside_neg = 0;    ///< normalised; 0 = off
  bool hold_i_outside = false;  ///< keep (not reset) the I-part outside the outer window
  double ff_w = 0;   ///< feed-forward of the set point
  double ff_dw = 0;  ///< feed-forward of the set point's rate (per s)
  double out_min = -1, out_max = 1;
};

class PidController {
 public:
  void set_parameters(const PidParameters& p) { p_ = p; }
  const PidParameters& parameters() const { return p_; }
  /// One control cycle: normalised deviation `e`, set point `w`, period `dt` (s).
  double update(double e, double w, double dt);
  void reset();
  double integral() const { return i_; }

 private:
  PidParameters p_;
  double i_ = 0;
  double last_e_ = 0;
  double last_w_ = 0;
  bool primed_ = false;
};

}  // namespace dsp408
