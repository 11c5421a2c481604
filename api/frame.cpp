#include <vplant/frame.h>

#include <cstdio>
#include <stdexcept>

#include "api/frame_convert.h"

namespace vplant {

Frame Frame::make(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  if (bytes.size() > 8) throw std::invalid_argument("a CAN frame has at most 8 data bytes");
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
