#include "tools/scenario/signal_expression.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>

#include "tools/scenario/yaml_fields.h"

namespace scenario {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

// Splits the trailing "* k / k + c - c" operations off the expression. Only the operators that
// follow the base are arithmetic; a '-' inside a name is part of the name.
void parse_arithmetic(std::string_view& rest, SignalExpr& e, const SourceMark& mark, std::string_view text) {
  while (true) {
    rest = trim(rest);
    if (rest.empty()) return;
    const char op = rest.front();
    if (op != '*' && op != '/' && op != '+' && op != '-')
      throw LoadError(mark, "signal '" + std::string(text) + "': unexpected '" + std::string(rest) + "'");
    rest.remove_prefix(1);
    rest = trim(rest);
    // The operand extends to the next operator that is not part of a number's exponent.
    std::size_t n = 0;
    while (n < rest.size()) {
      const char c = rest[n];
      if ((c == '*' || c == '/' || c == '+' || c == '-') && n > 0 && rest[n - 1] != 'e' && rest[n - 1] != 'E') break;
      if (c == ' ') break;
      ++n;
    }
    const auto v = parse_number(rest.substr(0, n));
    if (!v) throw LoadError(mark, "signal '" + std::string(text) + "': '" + std::string(rest.substr(0, n)) + "' is not a number");
    if (op == '*') {
      e.scale *= *v;
      e.offset *= *v;
    } else if (op == '/') {
      if (*v == 0) throw LoadError(mark, "signal '" + std::string(text) + "': division by zero");
      e.scale /= *v;
      e.offset /= *v;
    } else if (op == '+') {
      e.offset += *v;
    } else {
      e.offset -= *v;
    }
    rest.remove_prefix(n);
  }
}

}  // namespace

SignalExpr parse_signal(std::string_view text, const SourceMark& mark) {
  SignalExpr e;
  e.text = std::string(trim(text));
  e.mark = mark;
  std::string_view rest = trim(text);
  const auto bad = [&](const std::string& why) { return LoadError(mark, "signal '" + e.text + "': " + why); };
  if (rest.substr(0, 6) == "frame(") {
    e.kind = SignalExpr::Kind::Frame;
    rest.remove_prefix(6);
    const auto close = rest.find(')');
    if (close == std::string_view::npos) throw bad("missing ')'");
    std::string_view inside = trim(rest.substr(0, close));
    if (const auto colon = inside.find(':'); colon != std::string_view::npos) {
      e.frame.bus = std::string(trim(inside.substr(0, colon)));
      inside = trim(inside.substr(colon + 1));
    }
    const auto id = parse_integer(inside);
    if (!id || *id < 0 || *id > 0x1FFFFFFF) throw bad("'" + std::string(inside) + "' is not a CAN identifier");
    e.frame.id = static_cast<std::uint32_t>(*id);
    e.frame.extended = *id > 0x7FF;
    rest = trim(rest.substr(close + 1));
    if (rest.empty() || rest.front() != '[') throw bad("expected [byte] or [first:end] after frame(...)");
    const auto rb = rest.find(']');
    if (rb == std::string_view::npos) throw bad("missing ']'");
    const std::string_view range = rest.substr(1, rb - 1);
    const auto colon = range.find(':');
    std::optional<std::int64_t> first, end;
    if (colon == std::string_view::npos) {
      first = parse_integer(range);
      end = first ? std::optional<std::int64_t>(*first + 1) : std::nullopt;
    } else {
      first = parse_integer(range.substr(0, colon));
      end = parse_integer(range.substr(colon + 1));
    }
    if (!first || !end || *first < 0 || *end > 8 || *end <= *first) throw bad("byte range must be within [0:8]");
    e.frame.first = static_cast<int>(*first);
    e.frame.count = static_cast<int>(*end - *first);
    rest = trim(rest.substr(rb + 1));
    if (rest.substr(0, 3) == "as ") {
      rest = trim(rest.substr(3));
      std::size_t n = 0;
      while (n < rest.size() && std::isalnum(static_cast<unsigned char>(rest[n]))) ++n;
      const std::string type(rest.substr(0, n));
      rest.remove_prefix(n);
      const char kind = type.empty() ? '?' : type[0];
      const auto bits = parse_integer(type.size() > 1 ? std::string_view(type).substr(1) : std::string_view("x"));
      if ((kind != 'u' && kind != 'i' && kind != 'f') || !bits || *bits != e.frame.count * 8 ||
          (kind == 'f' && *bits != 32 && *bits != 64))
        throw bad("type '" + type + "' does not fit a " + std::to_string(e.frame.count) +
                  "-byte field (u8..u64, i8..i64, f32, f64)");
      e.frame.type = kind == 'u'   ? FrameField::Type::Unsigned
                     : kind == 'i' ? FrameField::Type::Signed
                     : *bits == 32 ? FrameField::Type::Float32
                                   : FrameField::Type::Float64;
    }
  } else {
    std::size_t n = 0;
    while (n < rest.size() && (is_name_char(rest[n]) || rest[n] == '.')) {
      // A '-' followed by a digit or space after a complete name is an operator, not part of it.
      if (rest[n] == '-' && n + 1 < rest.size() && (rest[n + 1] == ' ' || std::isdigit(static_cast<unsigned char>(rest[n + 1]))))
        break;
      ++n;
    }
    const std::string_view name = rest.substr(0, n);
    const auto dot = name.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot + 1 == name.size())
      throw bad("expected node.port, component.signal or frame(ID)[bytes]");
    e.owner = std::string(name.substr(0, dot));
    e.port = std::string(name.substr(dot + 1));
    rest.remove_prefix(n);
  }
  parse_arithmetic(rest, e, mark, e.text);
  return e;
}

double decode_field(const FrameField& field, const std::uint8_t* data, int dlc) {
  if (field.first + field.count > dlc) return std::numeric_limits<double>::quiet_NaN();
  std::uint64_t raw = 0;
  for (int i = field.count - 1; i >= 0; --i) raw = raw << 8 | data[field.first + i];
  switch (field.type) {
    case FrameField::Type::Unsigned:
      return static_cast<double>(raw);
    case FrameField::Type::Signed: {
      const int bits = field.count * 8;
      if (bits < 64 && (raw >> (bits - 1) & 1)) raw |= ~std::uint64_t{0} << bits;
      return static_cast<double>(static_cast<std::int64_t>(raw));
    }
    case FrameField::Type::Float32: {
      float f;
      const auto r = static_cast<std::uint32_t>(raw);
      std::memcpy(&f, &r, 4);
      return f;
    }
    case FrameField::Type::Float64: {
      double d;
      std::memcpy(&d, &raw, 8);
      return d;
    }
  }
  return 0;
}

}  // namespace scenario
