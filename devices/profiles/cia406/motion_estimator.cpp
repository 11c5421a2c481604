#include "devices/profiles/cia406/motion_estimator.h"

#include <algorithm>

namespace cia406 {

void MotionEstimator::configure(std::size_t window, double period_s) {
  window_ = std::max<std::size_t>(window, 1);
  span_s_ = static_cast<double>(window_) * period_s;
  positions_.assign(window_, last_);
  speeds_.assign(window_, 0.0);
  accels_.assign(window_, 0.0);
  reset(last_);
}

void MotionEstimator::reset(std::int64_t position) {
  last_ = position;
  std::fill(positions_.begin(), positions_.end(), position);
  std::fill(speeds_.begin(), speeds_.end(), 0.0);
  std::fill(accels_.begin(), accels_.end(), 0.0);
  next_ = 0;
  speed_ = accel_ = jerk_ = 0;
}

void MotionEstimator::push(std::int64_t position) {
  last_ = position;
  const std::int64_t old_position = positions_[next_];
  const double old_speed = speeds_[next_];
  const double old_accel = accels_[next_];
  speed_ = static_cast<double>(position - old_position) / span_s_;
  accel_ = (speed_ - old_speed) / span_s_;
  jerk_ = (accel_ - old_accel) / span_s_;
  positions_[next_] = position;
  speeds_[next_] = speed_;
  accels_[next_] = accel_;
  if (++next_ == window_) next_ = 0;  // next_ < window_ always: the modulo without a division
}

}  // namespace cia406
