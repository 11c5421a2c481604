// Private to the library: the public vplant::Frame to and from the simulator's sim::CanFrame.
#pragma once

#include <vplant/frame.h>

#include "sim/can_frame.h"

namespace vplant::detail {

inline sim::CanFrame to_sim(const Frame& f) {
  sim::CanFrame c;
  c.id = f.id;
  c.dlc = f.dlc > 8 ? 8 : f.dlc;
  c.extended = f.extended;
  c.rtr = f.rtr;
  c.data = f.data;
  return c;
}

inline Frame from_sim(const sim::CanFrame& c) {
  Frame f;
  f.id = c.id;
  f.dlc = c.dlc;
  f.extended = c.extended;
  f.rtr = c.rtr;
  f.data = c.data;
  return f;
}

}  // namespace vplant::detail
