#include "devices/canopen/data_type.h"

namespace canopen {

bool is_known_type(std::uint16_t code) {
  return (code >= 0x01 && code <= 0x0D) || code == 0x0F || (code >= 0x10 && code <= 0x16) || (code >= 0x18 && code <= 0x1B);
}

std::string_view type_name(DataType t) {
  switch (t) {
    case DataType::Boolean: return "BOOLEAN";
    case DataType::Integer8: return "INTEGER8";
    case DataType::Integer16: return "INTEGER16";
    case DataType::Integer32: return "INTEGER32";
    case DataType::Unsigned8: return "UNSIGNED8";
    case DataType::Unsigned16: return "UNSIGNED16";
    case DataType::Unsigned32: return "UNSIGNED32";
    case DataType::Real32: return "REAL32";
    case DataType::VisibleString: return "VISIBLE_STRING";
    case DataType::OctetString: return "OCTET_STRING";
    case DataType::UnicodeString: return "UNICODE_STRING";
    case DataType::TimeOfDay: return "TIME_OF_DAY";
    case DataType::TimeDifference: return "TIME_DIFFERENCE";
    case DataType::Domain: return "DOMAIN";
    case DataType::Integer24: return "INTEGER24";
    case DataType::Real64: return "REAL64";
    case DataType::Integer40: return "INTEGER40";
    case DataType::Integer48: return "INTEGER48";
    case DataType::Integer56: return "INTEGER56";
    case DataType::Integer64: return "INTEGER64";
    case DataType::Unsigned24: return "UNSIGNED24";
    case DataType::Unsigned40: return "UNSIGNED40";
    case DataType::Unsigned48: return "UNSIGNED48";
    case DataType::Unsigned56: return "UNSIGNED56";
    case DataType::Unsigned64: return "UNSIGNED64";
  }
  return "UNKNOWN";
}

}  // namespace canopen
