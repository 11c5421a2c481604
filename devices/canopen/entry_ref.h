// The one typed handle on an object-dictionary entry's value. Device and service code resolves an
// entry once (at construction) and then reads and writes its value as the C++ type it computes in,
// every tick, without a lookup, the generic decoder or an allocation: the value lives inline in the
// entry (stored_value.h), so a read is one load and a write one store.
//
// get() returns exactly what OdEntry::as<T>() returns and set() stores exactly what
// OdEntry::assign(T) stores (and so what ObjectDictionary::set<T>() stores): sign extension from a
// signed entry type, truncation to the entry's size, conversion to and from REAL32/REAL64. When T
// is the entry's own CiA type (uint16_t for UNSIGNED16, float for REAL32, ...) that is a plain
// copy. A value written by SDO or an RPDO is what get() returns next; a value set() stores is what
// an SDO upload or a TPDO sends next. Like set<T>(), set() runs no checks, hooks or observers:
// a device publishing its own process value is not a protocol write.
//
// Entry addresses are stable for the life of the dictionary (entries are only added or removed
// while it is built, before a Node owns it).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

template <typename T>
class EntryRef {
  static_assert(std::is_arithmetic_v<T>);

 public:
  /// Unbound (an optional object the product does not have): get() gives T{}.
  EntryRef() = default;
  /// Binds `entry`; throws std::invalid_argument when it is not a scalar (a string or domain).
  explicit EntryRef(OdEntry& entry) : e_(&entry), kind_(kind_of(entry)) {}
  /// Binds (index, sub) of `od`; throws std::invalid_argument when it is absent or not a scalar.
  EntryRef(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) : EntryRef(require(od, index, sub)) {}
  /// Binds (index, sub) when the dictionary has it, else stays unbound.
  static EntryRef optional(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) {
    OdEntry* e = od.entry(index, sub);
    return e ? EntryRef(*e) : EntryRef();
  }
  /// optional() for an entry pointer that may be null.
  static EntryRef optional(OdEntry* e) { return e ? EntryRef(*e) : EntryRef(); }

  bool bound() const { return e_ != nullptr; }
  explicit operator bool() const { return bound(); }
  OdEntry& entry() const { return *e_; }

  /// The value as T (entry().as<T>()); T{} when unbound.
  T get() const {
    if (!e_) return T{};
    const StoredValue& v = e_->value;
    if constexpr (std::endian::native == std::endian::little) {
      if (kind_ == Kind::Same && v.size() == sizeof(T)) [[likely]] {
        if constexpr (std::is_same_v<T, bool>) {
          return v.cell()[0] != 0;
        } else {
          T x;
          std::memcpy(&x, v.cell(), sizeof(T));
          return x;
        }
      }
      if (v.is_inline()) {
        std::uint64_t bits;
        std::memcpy(&bits, v.cell(), 8);  // the cell's tail is zero
        switch (kind_) {
          case Kind::Signed: {
            if (v.size() == 0) return T{};
            const unsigned shift = 64 - 8 * static_cast<unsigned>(v.size());
            return static_cast<T>(static_cast<std::int64_t>(bits << shift) >> shift);
          }
          case Kind::Unsigned: return static_cast<T>(bits);
          default: break;  // reals, and a resized entry of T's own type
        }
      }
    }
    return e_->as<T>();
  }

  /// Stores `v` as entry().assign(v) does; no checks, hooks or observers. Requires bound().
  void set(T v) const {
    StoredValue& s = e_->value;
    if constexpr (std::endian::native == std::endian::little) {
      if (kind_ == Kind::Same && s.size() == sizeof(T)) [[likely]] {
        if constexpr (std::is_same_v<T, bool>) {
          s.cell()[0] = v ? 1 : 0;
        } else {
          std::memcpy(s.cell(), &v, sizeof(T));
        }
        return;
      }
      if constexpr (std::is_integral_v<T>) {
        if ((kind_ == Kind::Signed || kind_ == Kind::Unsigned) && s.is_inline()) {
          encode_unsigned(static_cast<std::uint64_t>(v), std::span<std::uint8_t>(s.cell(), s.size()));  // as assign()
          return;
        }
      }
    }
    e_->assign(v);
  }

  /// Stores `v` rounded to the nearest integer and limited to [lo, hi] (integer limits): a process
  /// value published as an integer object (a temperature in °C, an actual value in increments).
  void set_rounded(double v, double lo, double hi) const
    requires std::is_integral_v<T>
  {
    const double c = v < lo ? lo : (v > hi ? hi : v);
    set(c == 0.0 ? T{0} : static_cast<T>(std::llround(c)));  // idle outputs publish 0 (not −0 rounding)
  }

 private:
  // How the entry's CiA type relates to T: Same is a plain copy; Signed/Unsigned are integers of
  // another width or signedness; Other converts through as<T>()/assign() (the reals).
  enum class Kind : std::uint8_t { Same, Signed, Unsigned, Other };

  static Kind kind_of(const OdEntry& e) {
    if (type_size(e.type) == 0) {
      throw std::invalid_argument("entry " + address(e.index, e.sub) + " is " + std::string(type_name(e.type)) +
                                  ": not a scalar value a typed handle can bind");
    }
    if (is_native(e.type)) return Kind::Same;
    if (is_real(e.type) || std::is_floating_point_v<T>) return Kind::Other;
    return is_signed_integer(e.type) ? Kind::Signed : Kind::Unsigned;
  }
  // True when values of T are stored as CiA type `type` byte for byte.
  static constexpr bool is_native(DataType type) {
    if constexpr (std::is_same_v<T, bool>) return type == DataType::Boolean;
    else if constexpr (std::is_same_v<T, std::int8_t>) return type == DataType::Integer8;
    else if constexpr (std::is_same_v<T, std::uint8_t>) return type == DataType::Unsigned8 || type == DataType::Boolean;
    else if constexpr (std::is_same_v<T, std::int16_t>) return type == DataType::Integer16;
    else if constexpr (std::is_same_v<T, std::uint16_t>) return type == DataType::Unsigned16;
    else if constexpr (std::is_same_v<T, std::int32_t>) return type == DataType::Integer32;
    else if constexpr (std::is_same_v<T, std::uint32_t>) return type == DataType::Unsigned32;
    else if constexpr (std::is_same_v<T, std::int64_t>) return type == DataType::Integer64;
    else if constexpr (std::is_same_v<T, std::uint64_t>) return type == DataType::Unsigned64;
    else if constexpr (std::is_same_v<T, float>) return type == DataType::Real32;
    else if constexpr (std::is_same_v<T, double>) return type == DataType::Real64;
    else return false;
  }
  static OdEntry& require(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) {
    OdEntry* e = od.entry(index, sub);
    if (!e) throw std::invalid_argument("object dictionary has no entry " + address(index, sub) + " to bind");
    return *e;
  }
  static std::string address(std::uint16_t index, std::uint8_t sub) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string s = "0x0000:00";
    for (int i = 0; i < 4; ++i) s[5 - i] = kHex[(index >> (4 * i)) & 0xF];
    s[7] = kHex[sub >> 4];
    s[8] = kHex[sub & 0xF];
    return s;
  }

  OdEntry* e_ = nullptr;
  Kind kind_ = Kind::Other;
};

}  // namespace canopen
