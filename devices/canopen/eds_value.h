// EDS value text <-> object dictionary bytes (CiA 306 §4.6.3: DefaultValue, LowLimit, HighLimit,
// ParameterValue). Integers: optional sign, 0x hex, leading-0 octal, decimal; `$NODEID+x`,
// `$NODEID + x`, `x+$NODEID` for node-relative integers. Reals: decimal notation. Strings as
// text; OCTET_STRING and DOMAIN as hex byte pairs; UNICODE_STRING as UTF-8 text.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "devices/canopen/object_dictionary.h"

namespace canopen::eds_detail {

struct Integer {
  bool negative = false;
  std::uint64_t magnitude = 0;
  int radix = 10;
};

/// A CiA 306 integer. On failure returns nullopt and sets `reason`.
std::optional<Integer> parse_integer(std::string_view text, std::string& reason);
/// A non-negative integer no larger than `max` (counts, flags, indices).
std::optional<std::uint64_t> parse_count(std::string_view text, std::uint64_t max, std::string& reason);

struct ParsedValue {
  Bytes bytes;
  bool node_relative = false;  ///< bytes hold the offset; the node-ID is added at reset
};

/// Parses `text` as a value of `type` (empty text = 0 / empty string). On failure returns nullopt
/// and sets `reason` (e.g. "300 is out of range for UNSIGNED8 (0..255)").
std::optional<ParsedValue> parse_value(DataType type, std::string_view text, bool allow_node_id, std::string& reason);

/// The EDS text of a value: small unsigned types and signed types in decimal, wider unsigned
/// types in 0x hex padded to their width, node-relative values as $NODEID+0x…, reals in the
/// shortest decimal form that reads back to the same bits.
std::string format_value(DataType type, std::span<const std::uint8_t> bytes, bool node_relative);

/// The value range of an integer type as text, e.g. "0..255" or "-128..127".
std::string range_text(DataType type);

}  // namespace canopen::eds_detail
