// A spool (or any mass-spring-damper positioner) that follows a command u through
//     x'' = w^2 (u - x) - 2 zeta w x',    |x| <= 1 (mechanical end of travel),
// advanced by the exact discretisation for u held over the step (zero-order hold), so its step
// response is the analytic one at every step size. Also returns the exact integral of x over the
// step, which the pump's swash plate needs (its angle integrates the pilot spool opening).
#pragma once

#include <Eigen/Dense>

namespace plant {

class SecondOrderLag {
 public:
  /// natural_frequency in rad/s, damping ratio zeta, step h in s.
  void configure(double natural_frequency, double damping, double h);
  /// Advances one step towards command u (clamped to [-1, 1]).
  void advance(double u);
  /// Holds the spool where it is (stuck spool): no motion, no integral.
  void hold() { velocity_ = 0.0; last_integral_ = position_ * h_; }

  double position() const { return position_; }
  double velocity() const { return velocity_; }
  /// Integral of the position over the last step (s).
  double last_integral() const { return last_integral_; }
  void reset(double position) { position_ = position; velocity_ = 0.0; last_integral_ = 0.0; }

 private:
  // Rows: position, velocity, integral; columns: position, velocity, command.
  Eigen::Matrix3d step_{Eigen::Matrix3d::Zero()};
  double h_ = 0.0;
  double position_ = 0.0;
  double velocity_ = 0.0;
  double last_integral_ = 0.0;
};

}  // namespace plant
