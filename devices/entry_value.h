// Per-cycle access to the value of an object-dictionary entry that device code resolved once (an
// OdEntry* from ObjectDictionary::entry(), stable for the dictionary's life): integer reads and
// writes inline, without the out-of-line type dispatch of OdEntry::as<T>() and encode_unsigned().
// The results are those of OdEntry::as<T>() (sign extension for signed types, then the cast to
// T) and of encode_unsigned() (little-endian two's complement, truncated or zero-padded to the
// entry's size); real types take the generic path. The value vector is read at every access,
// never held: a write or a reset may replace it.
#pragma once

#include <cstdint>
#include <type_traits>

#include "devices/canopen/object_dictionary.h"

namespace devices {

/// The value bytes of `e` (up to 8) as an unsigned little-endian number.
inline std::uint64_t entry_bits(const canopen::OdEntry& e) {
  const std::uint8_t* p = e.value.data();
  switch (e.value.size()) {
    case 0: return 0;
    case 1: return p[0];
    case 2: return static_cast<std::uint64_t>(p[0]) | static_cast<std::uint64_t>(p[1]) << 8;
    case 4:
      return static_cast<std::uint64_t>(p[0]) | static_cast<std::uint64_t>(p[1]) << 8 |
             static_cast<std::uint64_t>(p[2]) << 16 | static_cast<std::uint64_t>(p[3]) << 24;
    case 8: {
      std::uint64_t u = 0;
      for (int i = 7; i >= 0; --i) u = u << 8 | p[i];
      return u;
    }
    default: return canopen::decode_unsigned(e.value);
  }
}

/// Writes `v` into the value bytes of `e` in place, as encode_unsigned(v, e.value) does.
inline void store_entry_bits(canopen::OdEntry& e, std::uint64_t v) {
  std::uint8_t* p = e.value.data();
  switch (e.value.size()) {
    case 0: return;
    case 1: p[0] = static_cast<std::uint8_t>(v); return;
    case 2:
      p[0] = static_cast<std::uint8_t>(v);
      p[1] = static_cast<std::uint8_t>(v >> 8);
      return;
    case 4:
      p[0] = static_cast<std::uint8_t>(v);
      p[1] = static_cast<std::uint8_t>(v >> 8);
      p[2] = static_cast<std::uint8_t>(v >> 16);
      p[3] = static_cast<std::uint8_t>(v >> 24);
      return;
    case 8:
      for (int i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
      return;
    default: canopen::encode_unsigned(v, e.value);
  }
}

/// An entry resolved once, with its type's facts taken once: the per-cycle read is a few loads.
class BoundEntry {
 public:
  BoundEntry() = default;
  explicit BoundEntry(canopen::OdEntry* e)
      : e_(e),
        signed_(e && canopen::is_signed_integer(e->type)),
        real_(e && canopen::is_real(e->type)),
        word_(e && !real_ && canopen::type_size(e->type) == 4) {}

  canopen::OdEntry* entry() const { return e_; }
  explicit operator bool() const { return e_ != nullptr; }

  /// Same value as e->as<T>().
  template <typename T>
  T as() const {
    static_assert(std::is_integral_v<T>);
    const canopen::Bytes& v = e_->value;
    if (word_ && v.size() == 4) [[likely]] {  // the common 32-bit value: one straight decode, inline
      const std::uint8_t* p = v.data();
      const std::uint32_t u = static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                              static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
      return signed_ ? static_cast<T>(static_cast<std::int64_t>(static_cast<std::int32_t>(u))) : static_cast<T>(u);
    }
    return as_other<T>();
  }
  /// Publishes an integer as encode_unsigned(v, value) does (two's complement, truncated).
  template <typename T>
  void store(T v) const {
    static_assert(std::is_integral_v<T>);
    canopen::Bytes& bytes = e_->value;
    if (word_ && bytes.size() == 4) [[likely]] {
      const auto u = static_cast<std::uint64_t>(v);
      std::uint8_t* p = bytes.data();
      p[0] = static_cast<std::uint8_t>(u);
      p[1] = static_cast<std::uint8_t>(u >> 8);
      p[2] = static_cast<std::uint8_t>(u >> 16);
      p[3] = static_cast<std::uint8_t>(u >> 24);
      return;
    }
    store_entry_bits(*e_, static_cast<std::uint64_t>(v));
  }

 private:
  /// Any other width or type; kept out of line so the 32-bit path stays small where it is inlined.
  template <typename T>
  [[gnu::noinline]] T as_other() const {
    if (real_) return e_->as<T>();
    const canopen::Bytes& v = e_->value;
    const std::uint64_t u = entry_bits(*e_);
    if (!signed_) return static_cast<T>(u);
    const std::size_t n = v.size();
    if (n == 0) return 0;
    if (n < 8 && (v[n - 1] & 0x80)) return static_cast<T>(static_cast<std::int64_t>(u | ~std::uint64_t{0} << (8 * n)));
    return static_cast<T>(static_cast<std::int64_t>(u));
  }

  canopen::OdEntry* e_ = nullptr;
  bool signed_ = false;
  bool real_ = false;
  bool word_ = false;  ///< a 4-byte integer type
};

}  // namespace devices
