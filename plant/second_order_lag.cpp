#include "plant/second_order_lag.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>

namespace plant {

void SecondOrderLag::configure(double w, double zeta, double h) {
  // Augmented system z = [x, x', s, u] with s' = x and u' = 0; exp(M h) maps z(t) to z(t+h).
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 1) = 1.0;
  m(1, 0) = -w * w;
  m(1, 1) = -2.0 * zeta * w;
  m(1, 3) = w * w;
  m(2, 0) = 1.0;
  const Eigen::Matrix4d e = (m * h).exp();
  for (int row = 0; row < 3; ++row) {
    step_(row, 0) = e(row, 0);
    step_(row, 1) = e(row, 1);
    step_(row, 2) = e(row, 3);
  }
  h_ = h;
}

void SecondOrderLag::advance(double u) {
  u = std::clamp(u, -1.0, 1.0);
  const double x = step_(0, 0) * position_ + step_(0, 1) * velocity_ + step_(0, 2) * u;
  const double v = step_(1, 0) * position_ + step_(1, 1) * velocity_ + step_(1, 2) * u;
  last_integral_ = step_(2, 0) * position_ + step_(2, 1) * velocity_ + step_(2, 2) * u;
  position_ = x;
  velocity_ = v;
  // End of travel: the spool stops against its stop (the command is limited to the same range,
  // so this only acts on overshoot).
  if (position_ > 1.0 || position_ < -1.0) {
    position_ = std::clamp(position_, -1.0, 1.0);
    velocity_ = 0.0;
  }
}

}  // namespace plant
