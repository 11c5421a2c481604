// Per-cycle access to the value of an object-dictionary entry that device code resolved once (an
// OdEntry* from ObjectDictionary::entry(), stable for the dictionary's life), read and written as
// whatever integer type the device computes in. Unlike canopen::BoundEntry<T>, whose C++ type must
// be the entry's CiA type, an IntegerEntry reads exactly as OdEntry::as<T>() does (sign extension
// for signed types, then the cast to T), and store_entry_bits() writes as encode_unsigned() does
// (little-endian two's complement, truncated or zero-padded to the entry's size); real types take
// the generic path. The value vector is read at every access, never held: a write or a reset may
// replace it.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "devices/canopen/object_dictionary.h"

namespace devices {

/// The value bytes of `e` (up to 8) as an unsigned little-endian number.
inline std::uint64_t entry_bits(const canopen::OdEntry& e) { return canopen::decode_unsigned(e.value); }

/// Writes `v` into the value bytes of `e` in place, as encode_unsigned(v, e.value) does.
inline void store_entry_bits(canopen::OdEntry& e, std::uint64_t v) { canopen::encode_unsigned(v, e.value); }

/// An integer entry resolved once, with its type's facts taken once: the per-cycle read is a size
/// test and one load. Reads only (device code publishes through store_entry_bits()).
class IntegerEntry {
 public:
  IntegerEntry() = default;
  explicit IntegerEntry(const canopen::OdEntry* e)
      : e_(e),
        signed_(e && canopen::is_signed_integer(e->type)),
        direct_(e && !canopen::is_real(e->type) && std::endian::native == std::endian::little) {}

  const canopen::OdEntry* entry() const { return e_; }
  explicit operator bool() const { return e_ != nullptr; }

  /// Same value as e->as<T>(); 0 when unbound.
  template <typename T>
  T as() const {
    static_assert(std::is_integral_v<T>);
    if (direct_) [[likely]] return static_cast<T>(integer());
    return e_ ? e_->as<T>() : T{};
  }

 private:
  // An integer entry on a little-endian host: the common sizes by one load, the rest decoded.
  std::int64_t integer() const {
    const canopen::Bytes& v = e_->value;
    switch (v.size()) {
      case 1: return signed_ ? std::int64_t{static_cast<std::int8_t>(v[0])} : std::int64_t{v[0]};
      case 2: {
        std::uint16_t u;
        std::memcpy(&u, v.data(), 2);
        return signed_ ? std::int64_t{static_cast<std::int16_t>(u)} : std::int64_t{u};
      }
      case 4: {
        std::uint32_t u;
        std::memcpy(&u, v.data(), 4);
        return signed_ ? std::int64_t{static_cast<std::int32_t>(u)} : std::int64_t{u};
      }
      default:
        return signed_ ? canopen::decode_signed(v) : static_cast<std::int64_t>(canopen::decode_unsigned(v));
    }
  }

  const canopen::OdEntry* e_ = nullptr;
  bool signed_ = false;
  bool direct_ = false;  // bound, an integer type, little-endian host: integer() applies
};

}  // namespace devices
