// A command ramp (digest §4.3, A29): the ramp time is the time for a full-scale change (100 %
// for the angle, p_ref for the pressure), with the same slope up and down; time 0 = no ramp. The
// time of the set selected *now* applies, also while moving away from the previous set's value.
#pragma once

#include <algorithm>

namespace vtvpcd {

class CommandRamp {
 public:
  /// Advances one control period `dt_s` toward `target`.
  double step(double target, double ramp_time_s, double full_scale, double dt_s) {
    if (ramp_time_s <= 0.0) {
      value_ = target;
    } else {
      const double max_step = full_scale * dt_s / ramp_time_s;
      value_ += std::clamp(target - value_, -max_step, max_step);
    }
    return value_;
  }
  /// Restarts from `value` (bumpless start on enable).
  void reset(double value) { value_ = value; }
  double value() const { return value_; }

 private:
  double value_ = 0.0;
};

}  // namespace vtvpcd
