#include "devices/canopen/sdo_abort.h"

namespace canopen {

std::string_view describe(SdoAbort a) {
  switch (a) {
    case SdoAbort::None: return "no error";
    case SdoAbort::ToggleBit: return "toggle bit not alternated";
    case SdoAbort::Timeout: return "SDO protocol timed out";
    case SdoAbort::InvalidCommand: return "command specifier not valid or unknown";
    case SdoAbort::InvalidBlockSize: return "invalid block size";
    case SdoAbort::InvalidSequence: return "invalid sequence number";
    case SdoAbort::BlockCrc: return "CRC error";
    case SdoAbort::OutOfMemory: return "out of memory";
    case SdoAbort::UnsupportedAccess: return "unsupported access to an object";
    case SdoAbort::WriteOnly: return "attempt to read a write only object";
    case SdoAbort::ReadOnly: return "attempt to write a read only object";
    case SdoAbort::NoObject: return "object does not exist in the object dictionary";
    case SdoAbort::NotMappable: return "object cannot be mapped to the PDO";
    case SdoAbort::PdoLengthExceeded: return "number and length of objects to be mapped would exceed PDO length";
    case SdoAbort::ParameterIncompatible: return "general parameter incompatibility";
    case SdoAbort::InternalIncompatible: return "general internal incompatibility in the device";
    case SdoAbort::HardwareError: return "access failed due to a hardware error";
    case SdoAbort::TypeMismatch: return "data type does not match, length of service parameter does not match";
    case SdoAbort::LengthTooHigh: return "data type does not match, length of service parameter too high";
    case SdoAbort::LengthTooLow: return "data type does not match, length of service parameter too low";
    case SdoAbort::NoSubIndex: return "sub-index does not exist";
    case SdoAbort::InvalidValue: return "invalid value for parameter";
    case SdoAbort::ValueTooHigh: return "value of parameter written too high";
    case SdoAbort::ValueTooLow: return "value of parameter written too low";
    case SdoAbort::MaxLessThanMin: return "maximum value is less than minimum value";
    case SdoAbort::ResourceUnavailable: return "resource not available";
    case SdoAbort::General: return "general error";
    case SdoAbort::DataTransfer: return "data cannot be transferred or stored to the application";
    case SdoAbort::DataLocalControl: return "data cannot be transferred because of local control";
    case SdoAbort::DataDeviceState: return "data cannot be transferred because of the present device state";
    case SdoAbort::NoDictionary: return "object dictionary not present";
    case SdoAbort::NoData: return "no data available";
  }
  return "unknown abort code";
}

}  // namespace canopen
