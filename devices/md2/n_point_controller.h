// The MD2 controller's switching modes (§5.3, Wandfluh specific): solenoids are fully on or off
// depending on the control deviation e and a hysteresis h.
//   −6 2-point, 1 solenoid:  A on when e > h, off when e < −h, unchanged in between
//   −7 2-point, 2 solenoids: e > h → A on, B off; e < −h → B on, A off; unchanged in between
//   −8 3-point, 2 solenoids: e > h → A; e < −h → B; |e| ≤ h → both off
#pragma once

#include <cstdint>

namespace md2 {

class NPointController {
 public:
  struct Output {
    bool a = false;
    bool b = false;
  };
  Output update(std::int8_t mode, double e, double hysteresis);
  void reset() { state_ = {}; }

 private:
  Output state_;
};

}  // namespace md2
