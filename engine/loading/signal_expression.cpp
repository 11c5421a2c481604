#include "engine/loading/signal_expression.h"

#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>

#include "engine/loading/yaml_fields.h"

namespace scenario {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

bool is_operator(char c) { return c == '*' || c == '/' || c == '+' || c == '-'; }

// A number token extends to the next operator that is not the sign of an exponent, or a space.
std::string_view take_number(std::string_view rest) {
  std::size_t n = 0;
  while (n < rest.size()) {
    const char c = rest[n];
    if (c == ' ' || c == ')' || (is_operator(c) && n > 0 && rest[n - 1] != 'e' && rest[n - 1] != 'E')) break;
    if (is_operator(c) && n == 0) break;
    ++n;
  }
  return rest.substr(0, n);
}

// One signal: frame(...)[...] [as T], or node.port / component.signal. Consumes it from `rest`.
SignalExpr parse_base(std::string_view& rest, const std::function<LoadError(const std::string&)>& bad) {
  SignalExpr e;
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
    return e;
  }
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
    throw bad(name.empty() ? "expected a signal or a number at '" + std::string(rest) + "'"
                           : "expected node.port, component.signal or frame(ID)[bytes], not '" + std::string(name) + "'");
  e.owner = std::string(name.substr(0, dot));
  e.port = std::string(name.substr(dot + 1));
  rest.remove_prefix(n);
  return e;
}

bool starts_number(std::string_view rest) {
  return !rest.empty() && (std::isdigit(static_cast<unsigned char>(rest.front())) || rest.front() == '.');
}

}  // namespace

// expression := term (('+' | '-') term)*;  term := factor (('*' | '/') factor)*, at most one
// factor a signal and no division by a signal;  factor := signal | number.
SignalExpr parse_signal(std::string_view text, const SourceMark& mark) {
  SignalExpr e;
  e.text = std::string(trim(text));
  e.mark = mark;
  const std::function<LoadError(const std::string&)> bad = [&](const std::string& why) {
    return LoadError(mark, "signal '" + e.text + "': " + why);
  };
  std::string_view rest = trim(text);
  bool have_base = false;
  double sign = 1.0;
  if (!rest.empty() && rest.front() == '-') {  // a leading unary minus
    sign = -1.0;
    rest.remove_prefix(1);
  }
  while (true) {
    std::optional<SignalExpr> base;
    double coefficient = sign;
    bool divide = false;
    while (true) {
      rest = trim(rest);
      if (starts_number(rest)) {
        const auto token = take_number(rest);
        const auto v = parse_number(token);
        if (!v) throw bad("'" + std::string(token) + "' is not a number");
        if (divide && *v == 0) throw bad("division by zero");
        coefficient = divide ? coefficient / *v : coefficient * *v;
        rest.remove_prefix(token.size());
      } else {
        if (divide) throw bad("division by a signal");
        if (base) throw bad("a product of two signals is not supported");
        base = parse_base(rest, bad);
      }
      rest = trim(rest);
      if (rest.empty() || (rest.front() != '*' && rest.front() != '/')) break;
      divide = rest.front() == '/';
      rest.remove_prefix(1);
    }
    if (!base) {
      e.offset += coefficient;
    } else if (!have_base) {
      const auto keep_text = std::move(e.text);
      const auto keep_offset = e.offset;
      e = std::move(*base);
      e.text = keep_text;
      e.mark = mark;
      e.offset = keep_offset;
      e.scale = coefficient;
      have_base = true;
    } else {
      base->scale = coefficient;
      base->text = e.text;
      base->mark = mark;
      e.more.push_back(std::move(*base));
    }
    if (rest.empty()) break;
    if (rest.front() != '+' && rest.front() != '-') throw bad("unexpected '" + std::string(rest) + "'");
    sign = rest.front() == '+' ? 1.0 : -1.0;
    rest.remove_prefix(1);
    if (trim(rest).empty()) throw bad("missing operand after '" + std::string(1, sign > 0 ? '+' : '-') + "'");
  }
  if (!have_base) throw bad("expected node.port, component.signal or frame(ID)[bytes]");
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
