// Turbulent orifice flow Q = K * sign(dp) * sqrt(|dp|), regularised so it is smooth through dp = 0:
//     Q = K * dp / (dp^2 + d^2)^(1/4)
// This is linear (laminar-like) for |dp| << d and within (d/dp)^2/4 of the square root for
// |dp| >> d, admits reverse flow, and has a finite slope K/sqrt(d) at zero, which the implicit
// solver needs (the plain square root has an infinite one).
#pragma once

#include <cmath>

namespace plant {

struct FlowAndSlope {
  double q;       ///< m^3/s
  double dq_ddp;  ///< m^3/(s Pa)
};

/// k: flow coefficient (m^3/s per sqrt(Pa)), already multiplied by the opening; d: transition
/// pressure (Pa) below which the law turns linear.
inline FlowAndSlope orifice_flow(double k, double dp, double d) {
  const double s = dp * dp + d * d;
  const double inv_fourth_root = 1.0 / std::sqrt(std::sqrt(s));
  const double inv_square_root = inv_fourth_root * inv_fourth_root;  // 1/s = its square: no second division
  return {k * dp * inv_fourth_root, k * (0.5 * dp * dp + d * d) * inv_fourth_root * (inv_square_root * inv_square_root)};
}

}  // namespace plant
