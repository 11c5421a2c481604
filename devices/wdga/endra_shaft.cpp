#include "devices/wdga/endra_shaft.h"

#include <numbers>

namespace wdga {

double EndraShaft::revolutions(sim::Time now) {
  double rad;
  if (signal_.scripted()) {
    // The signal moves around the set angle; `speed` shows its derivative.
    rad = signal_.value(anchor_angle_ = angle, sim::seconds(now));
    speed = signal_.derivative(sim::seconds(now));
  } else {
    if (!anchored_ || angle != anchor_angle_) {
      anchor_angle_ = angle;  // the plant (or --set) moved the shaft: that is the position now
      anchor_time_ = now;
      anchored_ = true;
    }
    rad = anchor_angle_ + speed * sim::seconds(now - anchor_time_);
  }
  return rad / (2.0 * std::numbers::pi);
}

}  // namespace wdga
