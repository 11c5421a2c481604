// A typed reference to one object-dictionary entry, resolved once: device and service code that
// reads or publishes a value every tick binds it at construction instead of looking (index, sub)
// up and converting through the CiA type each time. The entry's little-endian bytes stay the
// single truth: get() and set() load and store them directly, so SDO and PDO see exactly what
// ObjectDictionary::set<T>() would have written, and a value written by SDO or PDO is what get()
// returns next. Like set<T>(), set() runs no checks, hooks or observers.
//
// The C++ type must be the entry's CiA type (uint16_t for UNSIGNED16, float for REAL32, bool or
// uint8_t for BOOLEAN, ...): a binding that would convert is refused at construction. Entry
// addresses are stable for the life of the dictionary (entries are only added or removed while
// it is built, before a Node owns it).
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

/// True when values of C++ type T are stored as CiA type `type` byte for byte.
template <typename T>
constexpr bool binds_as(DataType type) {
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

template <typename T>
class BoundEntry {
  static_assert(std::is_arithmetic_v<T>);

 public:
  /// Unbound (an optional object the product does not have): bound() is false.
  BoundEntry() = default;
  /// Binds (index, sub) of `od`; throws std::invalid_argument when it is absent or of another type.
  BoundEntry(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) : BoundEntry(require(od, index, sub)) {}
  /// Binds `entry`; throws std::invalid_argument when it is of another type.
  explicit BoundEntry(OdEntry& entry) : entry_(&entry) {
    if (!binds_as<T>(entry.type) || entry.value.size() != sizeof(T)) {
      throw std::invalid_argument("entry " + address(entry.index, entry.sub) + " is " + std::string(type_name(entry.type)) +
                                  " (" + std::to_string(entry.value.size()) + " bytes): cannot bind it as a " +
                                  std::to_string(sizeof(T)) + "-byte value of another type");
    }
  }
  /// Binds (index, sub) when the dictionary has it, else stays unbound; throws
  /// std::invalid_argument when it is there with another type.
  static BoundEntry optional(ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) {
    OdEntry* e = od.entry(index, sub);
    return e ? BoundEntry(*e) : BoundEntry();
  }

  bool bound() const { return entry_ != nullptr; }
  explicit operator bool() const { return bound(); }
  OdEntry& entry() const { return *entry_; }

  /// The current value (as the entry's as<T>() gives it).
  T get() const {
    if (entry_->value.size() != sizeof(T)) return entry_->as<T>();  // resized by set_bytes(): convert
    if constexpr (std::is_same_v<T, bool>) {
      return entry_->value[0] != 0;
    } else if constexpr (std::endian::native == std::endian::little) {
      T v;
      std::memcpy(&v, entry_->value.data(), sizeof(T));
      return v;
    } else {
      return entry_->as<T>();
    }
  }
  /// Stores `v` (the bytes ObjectDictionary::set<T>() stores); no checks, hooks or observers.
  void set(T v) const {
    if (entry_->value.size() != sizeof(T)) {
      entry_->assign(v);
    } else if constexpr (std::is_same_v<T, bool>) {
      entry_->value[0] = v ? 1 : 0;
    } else if constexpr (std::endian::native == std::endian::little) {
      std::memcpy(entry_->value.data(), &v, sizeof(T));
    } else {
      entry_->assign(v);
    }
  }

 private:
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

  OdEntry* entry_ = nullptr;
};

}  // namespace canopen
