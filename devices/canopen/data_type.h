// CiA 301 basic data types (the numeric codes are the ones EDS files use in DataType=).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace canopen {

enum class DataType : std::uint16_t {
  Boolean = 0x0001,
  Integer8 = 0x0002,
  Integer16 = 0x0003,
  Integer32 = 0x0004,
  Unsigned8 = 0x0005,
  Unsigned16 = 0x0006,
  Unsigned32 = 0x0007,
  Real32 = 0x0008,
  VisibleString = 0x0009,
  OctetString = 0x000A,
  UnicodeString = 0x000B,
  TimeOfDay = 0x000C,
  TimeDifference = 0x000D,
  Domain = 0x000F,
  Integer24 = 0x0010,
  Real64 = 0x0011,
  Integer40 = 0x0012,
  Integer48 = 0x0013,
  Integer56 = 0x0014,
  Integer64 = 0x0015,
  Unsigned24 = 0x0016,
  Unsigned40 = 0x0018,
  Unsigned48 = 0x0019,
  Unsigned56 = 0x001A,
  Unsigned64 = 0x001B,
};

// The predicates are inline: every typed read and write of a value asks them (per tick).

/// Size in bytes of a fixed-size type; 0 for strings and domains (variable length).
constexpr std::size_t type_size(DataType t) {
  switch (t) {
    case DataType::Boolean:
    case DataType::Integer8:
    case DataType::Unsigned8: return 1;
    case DataType::Integer16:
    case DataType::Unsigned16: return 2;
    case DataType::Integer24:
    case DataType::Unsigned24: return 3;
    case DataType::Integer32:
    case DataType::Unsigned32:
    case DataType::Real32: return 4;
    case DataType::Integer40:
    case DataType::Unsigned40: return 5;
    case DataType::Integer48:
    case DataType::Unsigned48:
    case DataType::TimeOfDay:
    case DataType::TimeDifference: return 6;
    case DataType::Integer56:
    case DataType::Unsigned56: return 7;
    case DataType::Integer64:
    case DataType::Unsigned64:
    case DataType::Real64: return 8;
    case DataType::VisibleString:
    case DataType::OctetString:
    case DataType::UnicodeString:
    case DataType::Domain: return 0;
  }
  return 0;
}
bool is_known_type(std::uint16_t code);
constexpr bool is_signed_integer(DataType t) {
  switch (t) {
    case DataType::Integer8:
    case DataType::Integer16:
    case DataType::Integer24:
    case DataType::Integer32:
    case DataType::Integer40:
    case DataType::Integer48:
    case DataType::Integer56:
    case DataType::Integer64: return true;
    default: return false;
  }
}
/// Includes Boolean.
constexpr bool is_unsigned_integer(DataType t) {
  switch (t) {
    case DataType::Boolean:
    case DataType::Unsigned8:
    case DataType::Unsigned16:
    case DataType::Unsigned24:
    case DataType::Unsigned32:
    case DataType::Unsigned40:
    case DataType::Unsigned48:
    case DataType::Unsigned56:
    case DataType::Unsigned64: return true;
    default: return false;
  }
}
constexpr bool is_real(DataType t) { return t == DataType::Real32 || t == DataType::Real64; }
/// Strings and domain.
constexpr bool is_variable_length(DataType t) { return type_size(t) == 0; }
std::string_view type_name(DataType t);  ///< e.g. "UNSIGNED16"

}  // namespace canopen
