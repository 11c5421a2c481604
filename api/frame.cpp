#include <vplant/frame.h>

#include <cstdio>
#include <string>

#include "api/frame_convert.h"

namespace vplant {

Frame Frame::make(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  if (bytes.size() > 8) {
    const std::string reason = "Frame::make: " + std::to_string(bytes.size()) +
                               " data bytes are out of range: a classic CAN frame has 0..8";
    detail::fail(reason);
  }
  if (id > sim::CanFrame::kMaxExtId) {
    const std::string reason = "Frame::make: identifier 0x" + detail::hex(id) +
                               " is out of range: 0x000..0x7FF (11-bit) or up to 0x1FFFFFFF (29-bit)";
    detail::fail(reason);
  }
  Frame f;
  f.id = id;
  f.extended = id > sim::CanFrame::kMaxStdId;
  f.dlc = static_cast<std::uint8_t>(bytes.size());
  std::size_t i = 0;
  for (auto b : bytes) f.data[i++] = b;
  return f;
}

// The format of sim::TraceWriter (virtual time: no epoch offset), so a trace built from
// Simulation::trace() is byte-identical to the one `vplant run --trace` writes.
std::string to_candump(const TimedFrame& t) {
  const long long us = t.time.count();
  char head[40];
  std::snprintf(head, sizeof head, "(%010lld.%06lld) ", us / 1000000, us % 1000000);
  char body[sim::kCandumpMax];
  sim::format_candump(detail::to_sim(t.frame), body);
  return head + t.bus + " " + body;
}

}  // namespace vplant
