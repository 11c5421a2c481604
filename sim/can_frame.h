// The CAN frame type every layer exchanges (classic CAN, 0..8 data bytes).
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace sim {

struct CanFrame {
  static constexpr std::uint32_t kMaxStdId = 0x7FF;
  static constexpr std::uint32_t kMaxExtId = 0x1FFFFFFF;

  std::uint32_t id = 0;     ///< 11-bit or 29-bit identifier (no flag bits)
  std::uint8_t dlc = 0;     ///< 0..8; for a remote frame the requested length
  bool extended = false;    ///< 29-bit identifier
  bool rtr = false;         ///< remote transmission request
  std::array<std::uint8_t, 8> data{};

  /// A data frame with the given bytes (at most 8).
  static CanFrame data_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes);
  static CanFrame data_frame(std::uint32_t id, std::span<const std::uint8_t> bytes);
  static CanFrame remote_frame(std::uint32_t id, std::uint8_t dlc);

  std::span<const std::uint8_t> payload() const { return {data.data(), rtr ? 0u : dlc}; }
  bool operator==(const CanFrame& o) const;
};

/// can-utils compact form without timestamp/interface: `601#4018100100000000`, `701#R1`.
std::string to_candump(const CanFrame& f);
/// Same, written into `out` (at least kCandumpMax bytes, NUL-terminated); returns the length.
inline constexpr std::size_t kCandumpMax = 32;
std::size_t format_candump(const CanFrame& f, char* out);
/// Parses the compact form (`ID#DATA`, `ID#R`, `ID#Rn`); nullopt if malformed.
std::optional<CanFrame> parse_candump(std::string_view text);

}  // namespace sim
