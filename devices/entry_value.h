// Per-cycle access to the value of an object-dictionary entry that device code resolved once (an
// OdEntry* from ObjectDictionary::entry(), stable for the dictionary's life), read and written as
// whatever integer type the device computes in. Unlike canopen::BoundEntry<T>, whose C++ type must
// be the entry's CiA type, an IntegerEntry converts exactly as OdEntry::as<T>() (sign extension
// for signed types, then the cast to T) and encode_unsigned() (little-endian two's complement,
// truncated or zero-padded to the entry's size) do; real types take the generic path. The value
// vector is read at every access, never held: a write or a reset may replace it.
#pragma once

#include <cstdint>
#include <type_traits>

#include "devices/canopen/object_dictionary.h"

namespace devices {

/// The value bytes of `e` (up to 8) as an unsigned little-endian number.
inline std::uint64_t entry_bits(const canopen::OdEntry& e) { return canopen::decode_unsigned(e.value); }

/// Writes `v` into the value bytes of `e` in place, as encode_unsigned(v, e.value) does.
inline void store_entry_bits(canopen::OdEntry& e, std::uint64_t v) { canopen::encode_unsigned(v, e.value); }

/// An entry resolved once, with its type's facts taken once: the per-cycle read is a few loads.
class IntegerEntry {
 public:
  IntegerEntry() = default;
  explicit IntegerEntry(canopen::OdEntry* e)
      : e_(e), signed_(e && canopen::is_signed_integer(e->type)), real_(e && canopen::is_real(e->type)) {}

  canopen::OdEntry* entry() const { return e_; }
  explicit operator bool() const { return e_ != nullptr; }

  /// Same value as e->as<T>().
  template <typename T>
  T as() const {
    static_assert(std::is_integral_v<T>);
    if (real_) [[unlikely]] return e_->as<T>();
    return signed_ ? static_cast<T>(canopen::decode_signed(e_->value)) : static_cast<T>(canopen::decode_unsigned(e_->value));
  }
  /// Publishes an integer as encode_unsigned(v, value) does (two's complement, truncated).
  template <typename T>
  void store(T v) const {
    static_assert(std::is_integral_v<T>);
    store_entry_bits(*e_, static_cast<std::uint64_t>(v));
  }

 private:
  canopen::OdEntry* e_ = nullptr;
  bool signed_ = false;
  bool real_ = false;
};

}  // namespace devices
