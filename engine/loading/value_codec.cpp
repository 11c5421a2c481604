#include "engine/loading/value_codec.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "devices/canopen/object_dictionary.h"

namespace scenario {

using canopen::DataType;

std::optional<DataType> type_from_name(const std::string& name) {
  struct Entry {
    const char* name;
    DataType type;
  };
  static constexpr Entry kTypes[] = {
      {"u8", DataType::Unsigned8},   {"u16", DataType::Unsigned16}, {"u24", DataType::Unsigned24},
      {"u32", DataType::Unsigned32}, {"u40", DataType::Unsigned40}, {"u48", DataType::Unsigned48},
      {"u56", DataType::Unsigned56}, {"u64", DataType::Unsigned64}, {"i8", DataType::Integer8},
      {"i16", DataType::Integer16},  {"i24", DataType::Integer24},  {"i32", DataType::Integer32},
      {"i40", DataType::Integer40},  {"i48", DataType::Integer48},  {"i56", DataType::Integer56},
      {"i64", DataType::Integer64},  {"f32", DataType::Real32},     {"f64", DataType::Real64},
      {"bool", DataType::Boolean},   {"string", DataType::VisibleString}};
  for (const auto& e : kTypes)
    if (name == e.name) return e.type;
  return std::nullopt;
}

std::string encode_literal(DataType type, const Literal& value, std::vector<std::uint8_t>& out) {
  const std::string tname(canopen::type_name(type));
  if (canopen::is_variable_length(type)) {
    if (type == DataType::VisibleString || type == DataType::UnicodeString) {
      out.assign(value.text.begin(), value.text.end());
      return {};
    }
    return "give octet strings and domains as 'data: HEX'";
  }
  const std::size_t size = canopen::type_size(type);
  out.assign(size, 0);
  if (canopen::is_real(type)) {
    if (value.kind == Literal::Kind::Text) return "'" + value.text + "' is not a number (" + tname + ")";
    const double v = value.as_double();
    if (type == DataType::Real32) {
      if (std::fabs(v) > std::numeric_limits<float>::max()) return "value " + value.text + " out of range for " + tname;
      const float f = static_cast<float>(v);
      std::memcpy(out.data(), &f, 4);
    } else {
      std::memcpy(out.data(), &v, 8);
    }
    return {};
  }
  std::int64_t v = 0;
  if (value.kind == Literal::Kind::Integer) {
    v = value.integer;
  } else if (type == DataType::Boolean && value.kind == Literal::Kind::Text && (value.text == "true" || value.text == "false")) {
    v = value.text == "true";
  } else {
    return "'" + value.text + "' is not an integer (" + tname + ")";
  }
  const int bits = static_cast<int>(size * 8);
  const bool hex_pattern = value.text.find("0x") != std::string::npos || value.text.find("0X") != std::string::npos;
  bool ok;
  if (type == DataType::Boolean) {
    ok = v == 0 || v == 1;
  } else if (canopen::is_signed_integer(type)) {
    const std::int64_t lo = bits == 64 ? INT64_MIN : -(std::int64_t{1} << (bits - 1));
    const std::int64_t hi = bits == 64 ? INT64_MAX : (std::int64_t{1} << (bits - 1)) - 1;
    // Hex literals may give the two's-complement pattern (0xFFFF for -1 in INTEGER16).
    const bool pattern_ok = hex_pattern && v >= 0 && (bits == 64 || static_cast<std::uint64_t>(v) >> bits == 0);
    ok = (v >= lo && v <= hi) || pattern_ok;
  } else {
    ok = (v >= 0 || (bits == 64 && hex_pattern)) && (bits == 64 || static_cast<std::uint64_t>(v) >> bits == 0);
  }
  if (!ok) return "value " + value.text + " out of range for " + tname;
  canopen::encode_unsigned(static_cast<std::uint64_t>(v), out);
  return {};
}

double decode_number(DataType type, std::span<const std::uint8_t> bytes) {
  if (canopen::is_variable_length(type)) return std::numeric_limits<double>::quiet_NaN();
  if (canopen::is_real(type)) return canopen::decode_real(type, bytes);
  if (canopen::is_signed_integer(type)) return static_cast<double>(canopen::decode_signed(bytes));
  return static_cast<double>(canopen::decode_unsigned(bytes));
}

std::string hex_bytes(std::span<const std::uint8_t> bytes) {
  std::string s;
  char buf[4];
  for (auto b : bytes) {
    std::snprintf(buf, sizeof buf, "%02X", b);
    if (!s.empty()) s += ' ';
    s += buf;
  }
  return s.empty() ? "(no data)" : s;
}

std::string object_address(std::uint16_t index, std::uint8_t sub) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%04X:%02X", index, sub);
  return buf;
}

std::string hex32(std::uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08X", v);
  return buf;
}

std::string describe_bytes(DataType type, std::span<const std::uint8_t> bytes) {
  if (type == DataType::VisibleString) return "\"" + std::string(bytes.begin(), bytes.end()) + "\"";
  if (canopen::is_variable_length(type)) return hex_bytes(bytes);
  if (canopen::is_real(type)) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", canopen::decode_real(type, bytes));
    return b;
  }
  char buf[48];
  if (canopen::is_signed_integer(type)) {
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(canopen::decode_signed(bytes)));
  } else {
    const auto u = canopen::decode_unsigned(bytes);
    std::snprintf(buf, sizeof buf, "%llu (0x%llX)", static_cast<unsigned long long>(u), static_cast<unsigned long long>(u));
  }
  return buf;
}

}  // namespace scenario
