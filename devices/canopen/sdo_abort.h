// CiA 301 SDO abort codes. The object dictionary's checks return these, so a refusal anywhere
// (access, range, a device's state machine) maps 1:1 to what the SDO server sends.
#pragma once

#include <cstdint>
#include <string_view>

namespace canopen {

enum class SdoAbort : std::uint32_t {
  None = 0,
  ToggleBit = 0x05030000,             ///< toggle bit not alternated
  Timeout = 0x05040000,               ///< SDO protocol timed out
  InvalidCommand = 0x05040001,        ///< client/server command specifier not valid or unknown
  InvalidBlockSize = 0x05040002,
  InvalidSequence = 0x05040003,
  BlockCrc = 0x05040004,
  OutOfMemory = 0x05040005,
  UnsupportedAccess = 0x06010000,     ///< unsupported access to an object
  WriteOnly = 0x06010001,             ///< attempt to read a write-only object
  ReadOnly = 0x06010002,              ///< attempt to write a read-only object
  NoObject = 0x06020000,              ///< object does not exist in the object dictionary
  NotMappable = 0x06040041,           ///< object cannot be mapped to the PDO
  PdoLengthExceeded = 0x06040042,     ///< number and length of mapped objects would exceed PDO length
  ParameterIncompatible = 0x06040043, ///< general parameter incompatibility
  InternalIncompatible = 0x06040047,  ///< general internal incompatibility in the device
  HardwareError = 0x06060000,         ///< access failed due to a hardware error
  TypeMismatch = 0x06070010,          ///< data type does not match, length of service parameter does not match
  LengthTooHigh = 0x06070012,         ///< data type does not match, length of service parameter too high
  LengthTooLow = 0x06070013,          ///< data type does not match, length of service parameter too low
  NoSubIndex = 0x06090011,            ///< sub-index does not exist
  InvalidValue = 0x06090030,          ///< invalid value for parameter (download only)
  ValueTooHigh = 0x06090031,          ///< value of parameter written too high
  ValueTooLow = 0x06090032,           ///< value of parameter written too low
  MaxLessThanMin = 0x06090036,        ///< maximum value is less than minimum value
  ResourceUnavailable = 0x060A0023,   ///< resource not available: SDO connection
  General = 0x08000000,               ///< general error
  DataTransfer = 0x08000020,          ///< data cannot be transferred or stored to the application
  DataLocalControl = 0x08000021,      ///< ... because of local control
  DataDeviceState = 0x08000022,       ///< ... because of the present device state
  NoDictionary = 0x08000023,          ///< object dictionary dynamic generation fails or no OD present
  NoData = 0x08000024,                ///< no data available
};

constexpr std::uint32_t code(SdoAbort a) { return static_cast<std::uint32_t>(a); }
std::string_view describe(SdoAbort a);

}  // namespace canopen
