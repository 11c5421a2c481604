// Power limitation (digest §4.4): 100 % power = p_ref x maximum flow, so the swivel angle that
// keeps the power at P_r is P_r * p_ref / p_ctrl; it rises hyperbolically as the pressure falls
// (1 bar floor) and never exceeds the pump's maximum angle. P_r = 0 forces zero flow.
#pragma once

#include <algorithm>

namespace vtvpcd {

inline double power_limit(double power_pct, double p_ref_bar, double p_ctrl_bar, double alpha_hi) {
  return std::min(alpha_hi, power_pct * p_ref_bar / std::max(p_ctrl_bar, 1.0));
}

}  // namespace vtvpcd
