// Publishing process values into object-dictionary entries every cycle without allocating
// (OdEntry::assign builds a new byte vector; this writes the existing bytes in place, inline).
#pragma once

#include <cstdint>
#include <type_traits>

#include "devices/canopen/object_dictionary.h"
#include "devices/entry_value.h"

namespace cia406 {

template <typename T>
void publish(canopen::OdEntry& e, T v) {
  static_assert(std::is_integral_v<T>);
  devices::store_entry_bits(e, static_cast<std::uint64_t>(v));  // two's complement, LE, truncated
}

}  // namespace cia406
