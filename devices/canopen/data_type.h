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

/// Size in bytes of a fixed-size type; 0 for strings and domains (variable length).
std::size_t type_size(DataType t);
bool is_known_type(std::uint16_t code);
bool is_signed_integer(DataType t);
bool is_unsigned_integer(DataType t);  ///< includes Boolean
bool is_real(DataType t);
bool is_variable_length(DataType t);   ///< strings and domain
std::string_view type_name(DataType t);  ///< e.g. "UNSIGNED16"

}  // namespace canopen
