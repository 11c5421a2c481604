#include "devices/canopen/eds_value.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>

#include "devices/canopen/eds_ini.h"

namespace canopen::eds_detail {

namespace {

int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 99;
}

std::string hex(std::uint64_t v, int width) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string out;
  do {
    out.insert(out.begin(), kDigits[v & 0xF]);
    v >>= 4;
  } while (v != 0);
  while (static_cast<int>(out.size()) < width) out.insert(out.begin(), '0');
  return out;
}

bool is_integer_type(DataType t) {
  return is_signed_integer(t) || is_unsigned_integer(t) || t == DataType::TimeOfDay || t == DataType::TimeDifference;
}

std::uint64_t max_unsigned(std::size_t bytes) {
  return bytes >= 8 ? std::numeric_limits<std::uint64_t>::max() : (std::uint64_t{1} << (8 * bytes)) - 1;
}

// Case-insensitive search for "$NODEID".
std::size_t find_node_id(std::string_view text) { return to_upper(text).find("$NODEID"); }

std::optional<ParsedValue> parse_integer_value(DataType type, std::string_view text, bool allow_node_id,
                                               std::string& reason) {
  const std::size_t size = type_size(type);
  ParsedValue out;
  std::string_view number = text;
  if (find_node_id(text) != std::string_view::npos) {
    if (!allow_node_id) {
      reason = "$NODEID is only supported in DefaultValue and ParameterValue";
      return std::nullopt;
    }
    // "$NODEID", "$NODEID+x", "x+$NODEID" (blanks around '+' allowed).
    const std::size_t plus = text.find('+');
    std::string_view a = trim(text.substr(0, plus));
    std::string_view b = plus == std::string_view::npos ? std::string_view{} : trim(text.substr(plus + 1));
    if (to_upper(b) == "$NODEID") std::swap(a, b);
    if (to_upper(a) != "$NODEID" || (plus != std::string_view::npos && b.empty()) || find_node_id(b) != std::string_view::npos) {
      reason = "'" + std::string(text) + "' is not of the form $NODEID+x";
      return std::nullopt;
    }
    if (b.find('+') != std::string_view::npos) {
      reason = "'" + std::string(text) + "' is not of the form $NODEID+x";
      return std::nullopt;
    }
    out.node_relative = true;
    number = b.empty() ? std::string_view("0") : b;
  }
  auto n = parse_integer(number, reason);
  if (!n) return std::nullopt;
  if (out.node_relative && n->negative) {
    reason = "negative offset in '" + std::string(text) + "'";
    return std::nullopt;
  }
  const auto range_error = [&] {
    reason = std::string(trim(number)) + " is out of range for " + std::string(type_name(type)) + " (" + range_text(type) + ")";
    return std::nullopt;
  };
  std::uint64_t bits = 0;
  if (type == DataType::Boolean) {
    if (n->magnitude > 1 || (n->negative && n->magnitude != 0)) return range_error();
    bits = n->magnitude;
  } else if (is_signed_integer(type)) {
    const std::uint64_t half = std::uint64_t{1} << (8 * size - 1);
    if (n->radix == 16 && !n->negative && n->magnitude <= max_unsigned(size)) {
      bits = n->magnitude;  // a hex literal is the two's complement bit pattern (0xFF = -1)
    } else if (n->negative) {
      if (n->magnitude > half) return range_error();
      bits = ~n->magnitude + 1;
    } else {
      if (n->magnitude > half - 1) return range_error();
      bits = n->magnitude;
    }
  } else {
    if ((n->negative && n->magnitude != 0) || n->magnitude > max_unsigned(size)) return range_error();
    bits = n->magnitude;
  }
  out.bytes.assign(size, 0);
  encode_unsigned(bits, out.bytes);
  return out;
}

std::optional<ParsedValue> parse_real_value(DataType type, std::string_view text, std::string& reason) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v, std::chars_format::general);
  if (ec != std::errc() || ptr != text.data() + text.size()) {
    std::string ignored;
    auto n = parse_integer(text, ignored);  // e.g. "0x10"
    if (!n) {
      reason = "'" + std::string(text) + "' is not a number";
      return std::nullopt;
    }
    v = static_cast<double>(n->magnitude);
    if (n->negative) v = -v;
  }
  const double limit = type == DataType::Real32 ? std::numeric_limits<float>::max() : std::numeric_limits<double>::max();
  if (!std::isfinite(v) || std::fabs(v) > limit) {
    reason = std::string(text) + " is out of range for " + std::string(type_name(type));
    return std::nullopt;
  }
  ParsedValue out;
  out.bytes = ObjectDictionary::encode(type, v);
  return out;
}

std::optional<ParsedValue> parse_hex_bytes(std::string_view text, std::string& reason) {
  ParsedValue out;
  int pending = -1;
  for (char c : text) {
    if (c == ' ' || c == '\t') continue;
    const int d = digit_value(c);
    if (d > 15) {
      reason = "'" + std::string(text) + "' is not a hex byte string";
      return std::nullopt;
    }
    if (pending < 0) {
      pending = d;
    } else {
      out.bytes.push_back(static_cast<std::uint8_t>(pending << 4 | d));
      pending = -1;
    }
  }
  if (pending >= 0) {
    reason = "odd number of hex digits in '" + std::string(text) + "'";
    return std::nullopt;
  }
  return out;
}

std::optional<ParsedValue> parse_unicode(std::string_view text, std::string& reason) {
  ParsedValue out;
  const auto put = [&](std::uint32_t unit) {
    out.bytes.push_back(static_cast<std::uint8_t>(unit));
    out.bytes.push_back(static_cast<std::uint8_t>(unit >> 8));
  };
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<std::uint8_t>(text[i]);
    std::uint32_t cp = 0;
    int extra = 0;
    if (c < 0x80) {
      cp = c;
    } else if ((c & 0xE0) == 0xC0) {
      cp = c & 0x1F;
      extra = 1;
    } else if ((c & 0xF0) == 0xE0) {
      cp = c & 0x0F;
      extra = 2;
    } else if ((c & 0xF8) == 0xF0) {
      cp = c & 0x07;
      extra = 3;
    } else {
      reason = "invalid UTF-8 in UNICODE_STRING";
      return std::nullopt;
    }
    if (i + static_cast<std::size_t>(extra) >= text.size()) {
      reason = "invalid UTF-8 in UNICODE_STRING";
      return std::nullopt;
    }
    for (int k = 1; k <= extra; ++k) {
      const auto cc = static_cast<std::uint8_t>(text[i + static_cast<std::size_t>(k)]);
      if ((cc & 0xC0) != 0x80) {
        reason = "invalid UTF-8 in UNICODE_STRING";
        return std::nullopt;
      }
      cp = cp << 6 | (cc & 0x3F);
    }
    i += 1 + static_cast<std::size_t>(extra);
    if (cp >= 0x10000) {
      cp -= 0x10000;
      put(0xD800 | (cp >> 10));
      put(0xDC00 | (cp & 0x3FF));
    } else {
      put(cp);
    }
  }
  return out;
}

std::string format_unicode(std::span<const std::uint8_t> bytes) {
  std::string out;
  const auto emit = [&](std::uint32_t cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  };
  for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) {
    std::uint32_t unit = bytes[i] | static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (unit >= 0xD800 && unit < 0xDC00 && i + 3 < bytes.size()) {
      const std::uint32_t low = bytes[i + 2] | static_cast<std::uint32_t>(bytes[i + 3]) << 8;
      if (low >= 0xDC00 && low < 0xE000) {
        emit(0x10000 + ((unit - 0xD800) << 10) + (low - 0xDC00));
        i += 2;
        continue;
      }
    }
    emit(unit);
  }
  return out;
}

template <typename F>
std::string shortest(F v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), v);
  return ec == std::errc() ? std::string(buf, ptr) : std::string("0");
}

}  // namespace

std::optional<Integer> parse_integer(std::string_view text, std::string& reason) {
  const std::string_view original = trim(text);
  std::string_view s = original;
  Integer n;
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) {
    n.negative = s.front() == '-';
    s.remove_prefix(1);
  }
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    n.radix = 16;
    s.remove_prefix(2);
  } else if (s.size() > 1 && s[0] == '0') {
    n.radix = 8;  // CiA 306: a leading 0 means octal
    s.remove_prefix(1);
  }
  if (s.empty()) {
    reason = "'" + std::string(original) + "' is not a number";
    return std::nullopt;
  }
  for (char c : s) {
    const int d = digit_value(c);
    if (d >= n.radix) {
      reason = "'" + std::string(original) + "' is not a number";
      return std::nullopt;
    }
    const auto radix = static_cast<std::uint64_t>(n.radix);
    if (n.magnitude > (std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(d)) / radix) {
      reason = "'" + std::string(original) + "' is too large";
      return std::nullopt;
    }
    n.magnitude = n.magnitude * radix + static_cast<std::uint64_t>(d);
  }
  return n;
}

std::optional<std::uint64_t> parse_count(std::string_view text, std::uint64_t max, std::string& reason) {
  auto n = parse_integer(text, reason);
  if (!n) return std::nullopt;
  if ((n->negative && n->magnitude != 0) || n->magnitude > max) {
    reason = std::string(trim(text)) + " is out of range (0.." + std::to_string(max) + ")";
    return std::nullopt;
  }
  return n->magnitude;
}

std::optional<ParsedValue> parse_value(DataType type, std::string_view text, bool allow_node_id, std::string& reason) {
  text = trim(text);
  if (text.empty()) {
    ParsedValue empty;
    empty.bytes.assign(type_size(type), 0);
    return empty;
  }
  if (is_integer_type(type)) return parse_integer_value(type, text, allow_node_id, reason);
  if (find_node_id(text) != std::string_view::npos && type != DataType::VisibleString) {
    reason = "$NODEID needs an integer type, not " + std::string(type_name(type));
    return std::nullopt;
  }
  switch (type) {
    case DataType::Real32:
    case DataType::Real64: return parse_real_value(type, text, reason);
    case DataType::VisibleString: {
      ParsedValue out;
      out.bytes.assign(text.begin(), text.end());
      return out;
    }
    case DataType::UnicodeString: return parse_unicode(text, reason);
    case DataType::OctetString:
    case DataType::Domain: return parse_hex_bytes(text, reason);
    default: break;
  }
  reason = "no value syntax for " + std::string(type_name(type));
  return std::nullopt;
}

std::string format_value(DataType type, std::span<const std::uint8_t> bytes, bool node_relative) {
  if (node_relative) return "$NODEID+0x" + hex(decode_unsigned(bytes), 0);
  switch (type) {
    case DataType::Boolean:
    case DataType::Unsigned8:
    case DataType::Unsigned16:
    case DataType::TimeOfDay:
    case DataType::TimeDifference: return std::to_string(decode_unsigned(bytes));
    case DataType::Unsigned24:
    case DataType::Unsigned32:
    case DataType::Unsigned40:
    case DataType::Unsigned48:
    case DataType::Unsigned56:
    case DataType::Unsigned64: return "0x" + hex(decode_unsigned(bytes), static_cast<int>(2 * type_size(type)));
    case DataType::Integer8:
    case DataType::Integer16:
    case DataType::Integer24:
    case DataType::Integer32:
    case DataType::Integer40:
    case DataType::Integer48:
    case DataType::Integer56:
    case DataType::Integer64: return std::to_string(decode_signed(bytes));
    case DataType::Real32: {
      float f = 0;
      if (bytes.size() >= 4) std::memcpy(&f, bytes.data(), 4);
      return shortest(f);
    }
    case DataType::Real64: {
      double d = 0;
      if (bytes.size() >= 8) std::memcpy(&d, bytes.data(), 8);
      return shortest(d);
    }
    case DataType::VisibleString: return std::string(bytes.begin(), bytes.end());
    case DataType::UnicodeString: return format_unicode(bytes);
    case DataType::OctetString:
    case DataType::Domain: {
      std::string out;
      for (auto b : bytes) out += hex(b, 2);
      return out;
    }
  }
  return {};
}

std::string range_text(DataType type) {
  const std::size_t size = type_size(type);
  if (type == DataType::Boolean) return "0..1";
  if (is_signed_integer(type)) {
    const std::uint64_t half = std::uint64_t{1} << (8 * size - 1);
    return "-" + std::to_string(half) + ".." + std::to_string(half - 1);
  }
  return "0.." + std::to_string(max_unsigned(size));
}

}  // namespace canopen::eds_detail
