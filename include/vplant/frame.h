// vplant public API: CAN frames and simulated time as the library hands them to its caller.
// Self-contained (standard library only), like every header under <vplant/...>.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace vplant {

/// Simulated time since the start of the run (virtual time: microsecond resolution, exact).
using Time = std::chrono::microseconds;
/// A span of simulated time; `std::chrono` literals convert (`sim.run_for(500ms)`).
using Duration = std::chrono::microseconds;

/// A classic CAN frame (0..8 data bytes).
struct Frame {
  std::uint32_t id = 0;    ///< 11-bit or 29-bit identifier, no flag bits
  std::uint8_t dlc = 0;    ///< 0..8; for a remote frame the requested length
  bool extended = false;   ///< 29-bit identifier
  bool rtr = false;        ///< remote transmission request
  std::array<std::uint8_t, 8> data{};

  /// A data frame with up to 8 bytes; an identifier above 7FFh makes it extended. More bytes or
  /// an identifier above 1FFFFFFFh throw vplant::Error (<vplant/error.h>) naming the valid range.
  static Frame make(std::uint32_t id, std::initializer_list<std::uint8_t> bytes);
  friend bool operator==(const Frame&, const Frame&) = default;
};

/// A frame as it crossed a bus, with the simulated time it was delivered.
struct TimedFrame {
  Time time{};
  std::string bus;  ///< the scenario's bus name
  Frame frame;
};

/// One line of can-utils' `candump -L` log, as `vplant run --trace` writes it:
/// `(0000000000.012000) main 602#2B4060000F000000` (no newline).
std::string to_candump(const TimedFrame& f);

}  // namespace vplant
