// Private to the library: the public vplant::Frame to and from the simulator's sim::CanFrame.
#pragma once

#include <vplant/frame.h>

#include <cstdio>
#include <string>

#include "api/error_convert.h"
#include "sim/can_frame.h"

namespace vplant::detail {

/// `v` in upper-case hex, at least `width` digits (zero-padded), for error messages.
inline std::string hex(std::uint64_t v, int width = 1) {
  char s[24];
  std::snprintf(s, sizeof s, "%0*llX", width, static_cast<unsigned long long>(v));
  return s;
}

/// Refuses a frame classic CAN cannot carry (a DLC of 9..15 is CAN FD's, an identifier beyond its
/// format) rather than clamping it: the caller's master would send something else on a real bus.
inline void check(const Frame& f, const char* call) {
  std::string reason;
  if (f.dlc > 8)
    reason = std::string(call) + ": DLC " + std::to_string(f.dlc) + " is out of range: a classic CAN frame has DLC 0..8";
  else if (!f.extended && f.id > sim::CanFrame::kMaxStdId)
    reason = std::string(call) + ": identifier 0x" + hex(f.id) + " is out of range: an 11-bit identifier is 0x000..0x7FF (set extended for 29 bits)";
  else if (f.id > sim::CanFrame::kMaxExtId)
    reason = std::string(call) + ": identifier 0x" + hex(f.id) + " is out of range: a 29-bit identifier is 0x00000000..0x1FFFFFFF";
  if (!reason.empty()) fail(reason);
}

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
