// Publishing process values into object-dictionary entries once per control cycle without
// allocating (ObjectDictionary::set and OdEntry::assign build a temporary byte vector).
#pragma once

#include <cmath>
#include <cstdint>

#include "devices/canopen/object_dictionary.h"

namespace dsp408 {

/// Writes an integer into an entry of any integer type (two's complement, truncated to its size).
inline void put(canopen::OdEntry& e, std::int64_t v) { canopen::encode_unsigned(static_cast<std::uint64_t>(v), e.value); }
/// Rounds to the nearest integer, limited to [lo, hi], and writes it.
inline void put_rounded(canopen::OdEntry& e, double v, double lo, double hi) {
  const double c = v < lo ? lo : (v > hi ? hi : v);
  put(e, c == 0.0 ? 0 : static_cast<std::int64_t>(std::llround(c)));  // idle outputs publish 0 every cycle
}

}  // namespace dsp408
