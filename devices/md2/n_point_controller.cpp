#include "devices/md2/n_point_controller.h"

#include "devices/md2/control_mode.h"

namespace md2 {

NPointController::Output NPointController::update(std::int8_t m, double e, double h) {
  switch (m) {
    case mode::kTwoPoint1:
      if (e > h) state_.a = true;
      if (e < -h) state_.a = false;
      state_.b = false;
      break;
    case mode::kTwoPoint2:
      if (e > h) state_ = {true, false};
      if (e < -h) state_ = {false, true};
      break;
    case mode::kThreePoint:
      state_ = {e > h, e < -h};
      break;
    default: state_ = {}; break;
  }
  return state_;
}

}  // namespace md2
