// Frame patterns for waits, frame assertions and wire faults: an identifier with a mask, and
// optionally the data with wildcards: "2F 40 60 00 ?? ?? ?? ??" (exactly 8 bytes), "80 ?? *"
// (at least 2 bytes, `*` = any further bytes), "" (no data: DLC 0).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "sim/can_frame.h"

namespace scenario {

struct FramePattern {
  std::uint32_t id = 0;
  std::uint32_t mask = 0x7FF;  ///< bits of the identifier that must equal `id`
  bool extended = false;
  bool any_data = true;        ///< no data pattern given
  int length = 0;              ///< data bytes in the pattern
  bool open_end = false;       ///< `*`: longer frames match too
  std::array<std::uint8_t, 8> value{};
  std::array<std::uint8_t, 8> care{};  ///< 0xFF where the byte must equal value

  bool matches_id(const sim::CanFrame& f) const {
    return f.extended == extended && !f.rtr && ((f.id ^ id) & mask) == 0;
  }
  bool matches_data(const sim::CanFrame& f) const {
    if (any_data) return true;
    if (f.dlc < length || (!open_end && f.dlc != length)) return false;
    for (int i = 0; i < length; ++i)
      if ((f.data[static_cast<std::size_t>(i)] ^ value[static_cast<std::size_t>(i)]) & care[static_cast<std::size_t>(i)]) return false;
    return true;
  }
  bool matches(const sim::CanFrame& f) const { return matches_id(f) && matches_data(f); }
  std::string describe() const;
};

/// Parses a data pattern into `p`; returns an error message, empty on success.
std::string parse_data_pattern(std::string_view text, FramePattern& p);

}  // namespace scenario
