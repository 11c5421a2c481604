#include "devices/profiles/dsp408/command_value_ramp.h"

#include <algorithm>
#include <limits>

namespace dsp408 {

double CommandValueRamp::rate(double seconds) const {
  return seconds > 0 ? full_scale_ / seconds : std::numeric_limits<double>::infinity();
}

double CommandValueRamp::step(double target, double dt) {
  if (!enabled_) return output_ = target;
  double left = dt;
  // At most two segments: down to 0, then up on the other side.
  for (int segment = 0; segment < 2 && left > 0 && output_ != target; ++segment) {
    double rate_now;
    double stop;  // where this segment ends at the latest
    if (output_ >= 0 && target > output_) {
      rate_now = rate(times_.a_up);
      stop = target;
    } else if (output_ > 0 && target < output_) {
      rate_now = rate(times_.a_down);
      stop = std::max(target, 0.0);
    } else if (output_ <= 0 && target < output_) {
      rate_now = rate(times_.b_up);
      stop = target;
    } else {  // output_ < 0 && target > output_
      rate_now = rate(times_.b_down);
      stop = std::min(target, 0.0);
    }
    const double distance = stop > output_ ? stop - output_ : output_ - stop;
    const double needed = distance / rate_now;  // 0 for a step
    // A relative tolerance keeps rounding of many small steps from costing an extra cycle.
    if (needed <= left * (1 + 1e-9)) {
      output_ = stop;
      left = std::max(0.0, left - needed);
    } else {
      output_ += (stop > output_ ? 1 : -1) * rate_now * left;
      left = 0;
    }
  }
  return output_;
}

double CommandValueRamp::time_to(double target) const {
  auto seconds = [this](double time, double distance) { return time > 0 ? distance / full_scale_ * time : 0.0; };
  double r = output_, t = 0;
  if (r > 0 && target < r) {  // A side falling (to the target or to 0)
    const double stop = std::max(target, 0.0);
    t += seconds(times_.a_down, r - stop);
    r = stop;
  } else if (r < 0 && target > r) {  // B side falling
    const double stop = std::min(target, 0.0);
    t += seconds(times_.b_down, stop - r);
    r = stop;
  }
  if (target > r) t += seconds(times_.a_up, target - r);
  if (target < r) t += seconds(times_.b_up, r - target);
  return t;
}

double RateLimiter::step(double target, double dt) {
  if (target > output_) {
    output_ = rise_ > 0 ? std::min(target, output_ + rise_ * dt) : target;
  } else if (target < output_) {
    output_ = fall_ > 0 ? std::max(target, output_ - fall_ * dt) : target;
  }
  return output_;
}

}  // namespace dsp408
