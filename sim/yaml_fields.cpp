#include "sim/yaml_fields.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cctype>
#include <set>

#include <yaml-cpp/depthguard.h>

namespace sim {

namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t");
  return std::string(s.substr(b, e - b + 1));
}

std::string fmt_double(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

[[noreturn]] void fail(const YAML::Node& n, const std::string& file, const std::string& reason) {
  throw DiagnosticError(mark_of(n, file), reason);
}

std::string scalar_or_fail(const YAML::Node& n, const std::string& file, std::string_view what) {
  if (!n || !n.IsScalar()) fail(n, file, std::string(what) + ": expected a scalar value");
  return n.Scalar();
}

}  // namespace

YAML::Node parse_yaml(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw DiagnosticError(SourceMark{file, e.mark.line + 1, e.mark.column + 1},
                          "nesting deeper than " + std::to_string(e.depth() - 1) + " levels (the YAML parser's limit)");
  } catch (const YAML::ParserException& e) {
    throw DiagnosticError(SourceMark{file, e.mark.line + 1, e.mark.column + 1}, "YAML syntax error: " + e.msg);
  }
}

SourceMark mark_of(const YAML::Node& node, const std::string& file) {
  SourceMark m{file, 0, 0};
  if (node.IsDefined()) {
    const auto mk = node.Mark();
    if (mk.line >= 0) {
      m.line = mk.line + 1;
      m.column = mk.column + 1;
    }
  }
  return m;
}

// ---- MapReader ----------------------------------------------------------------------------------

MapReader::MapReader(const YAML::Node& node, std::string file, std::string what)
    : node_(node), file_(std::move(file)), what_(std::move(what)) {
  if (!node_.IsMap()) throw DiagnosticError(mark_of(node_, file_), what_ + ": expected a mapping of keys");
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) throw DiagnosticError(mark_of(kv.first, file_), what_ + ": keys must be plain names");
    if (!seen.insert(kv.first.Scalar()).second)
      throw DiagnosticError(mark_of(kv.first, file_), what_ + ": duplicate key '" + kv.first.Scalar() + "'");
  }
}

bool MapReader::has(std::string_view key) const {
  for (const auto& kv : node_)
    if (kv.first.Scalar() == key) return true;
  return false;
}

YAML::Node MapReader::get(std::string_view key) {
  if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.emplace_back(key);
  for (const auto& kv : node_)
    if (kv.first.Scalar() == key) return kv.second;
  return YAML::Node(YAML::NodeType::Undefined);
}

YAML::Node MapReader::require(std::string_view key) {
  YAML::Node n = get(key);
  if (!n.IsDefined()) throw DiagnosticError(mark(), what_ + ": missing key '" + std::string(key) + "'");
  return n;
}

SourceMark MapReader::key_mark(std::string_view key) const {
  for (const auto& kv : node_)
    if (kv.first.Scalar() == key) return mark_of(kv.first, file_);
  return mark();
}

void MapReader::finish() const {
  for (const auto& kv : node_) {
    const auto& k = kv.first.Scalar();
    if (std::find(asked_.begin(), asked_.end(), k) != asked_.end()) continue;
    std::string known;
    for (const auto& a : asked_) known += (known.empty() ? "" : ", ") + a;
    throw DiagnosticError(mark_of(kv.first, file_),
                          "unknown key '" + k + "' in " + what_ + (known.empty() ? "" : " (known: " + known + ")"));
  }
}

std::string MapReader::one_of(const std::vector<std::string>& choices) {
  std::string found;
  for (const auto& c : choices) {
    if (!has(c)) continue;
    if (!found.empty())
      throw DiagnosticError(key_mark(c), what_ + ": '" + found + "' and '" + c + "' cannot be combined");
    found = c;
  }
  if (found.empty()) {
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
    // Report an unknown key, if there is one, as the likely typo.
    for (const auto& kv : node_) {
      const auto& k = kv.first.Scalar();
      if (std::find(asked_.begin(), asked_.end(), k) == asked_.end() &&
          std::find(choices.begin(), choices.end(), k) == choices.end())
        throw DiagnosticError(mark_of(kv.first, file_), "unknown key '" + k + "' in " + what_ + " (expected one of: " + list + ")");
    }
    throw DiagnosticError(mark(), what_ + ": expected one of: " + list);
  }
  get(found);
  return found;
}

// ---- text parsers -------------------------------------------------------------------------------

std::optional<std::int64_t> parse_integer(std::string_view text) {
  std::string s = trim(text);
  if (s.empty()) return std::nullopt;
  bool neg = false;
  std::size_t i = 0;
  if (s[0] == '-' || s[0] == '+') {
    neg = s[0] == '-';
    i = 1;
  }
  int base = 10;
  if (s.size() > i + 2 && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X')) {
    base = 16;
    i += 2;
  } else if (s.size() > i + 2 && s[i] == '0' && (s[i + 1] == 'b' || s[i + 1] == 'B')) {
    base = 2;
    i += 2;
  }
  if (i >= s.size()) return std::nullopt;
  std::uint64_t v = 0;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    int d;
    if (c >= '0' && c <= '9') d = c - '0';
    else if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
    else return std::nullopt;
    if (d >= base) return std::nullopt;
    if (v > (UINT64_MAX - static_cast<std::uint64_t>(d)) / static_cast<std::uint64_t>(base)) return std::nullopt;
    v = v * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(d);
  }
  // Hex/binary up to 64 bits keep their bit pattern; decimal must fit int64.
  if (base == 10 && v > static_cast<std::uint64_t>(INT64_MAX) + (neg ? 1u : 0u)) return std::nullopt;
  const auto sv = static_cast<std::int64_t>(v);
  return neg ? -sv : sv;
}

std::optional<double> parse_number(std::string_view text) {
  if (auto i = parse_integer(text)) return static_cast<double>(*i);
  std::string s = trim(text);
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<sim::Duration> parse_duration(std::string_view text, std::string* problem) {
  std::string s = trim(text);
  struct Unit {
    const char* suffix;
    double seconds;
  };
  static constexpr Unit kUnits[] = {{"us", 1e-6}, {"ms", 1e-3}, {"min", 60.0}, {"s", 1.0}};
  double scale = 1.0;
  for (const auto& u : kUnits) {
    const std::string suf = u.suffix;
    if (s.size() > suf.size() && s.compare(s.size() - suf.size(), suf.size(), suf) == 0) {
      s = trim(s.substr(0, s.size() - suf.size()));
      scale = u.seconds;
      break;
    }
  }
  auto v = parse_number(s);
  if (!v && !s.empty()) {
    // A number too large for a double (1e400, inf) is a number all the same: out of range.
    char* end = nullptr;
    const double huge = std::strtod(s.c_str(), &end);
    if (end == s.c_str() + s.size() && !std::isnan(huge) && std::fabs(huge) >= 1) v = huge;
  }
  const char* why = nullptr;
  if (!v) {
    why = "is not a duration (e.g. 10ms, 1.5s, 250us)";
  } else if (*v < 0) {
    why = "is negative (a duration is 0 or more)";
  } else if (*v * scale > kMaxDurationSeconds) {
    why = "is out of range (at most 1e9 s, about 31 years)";
  }
  if (why) {
    if (problem) *problem = why;
    return std::nullopt;
  }
  return sim::from_seconds(*v * scale);
}

// ---- YAML scalars -------------------------------------------------------------------------------

std::string read_string(const YAML::Node& n, const std::string& file, std::string_view what) {
  return scalar_or_fail(n, file, what);
}

std::string read_name(const YAML::Node& n, const std::string& file, std::string_view what) {
  const auto s = scalar_or_fail(n, file, what);
  const bool ok = !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_') &&
                  std::all_of(s.begin(), s.end(), [](char c) {
                    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
                  });
  if (!ok) fail(n, file, std::string(what) + ": '" + s + "' is not a valid name (letters, digits, '_', '-')");
  return s;
}

double read_number(const YAML::Node& n, const std::string& file, std::string_view what) {
  const auto s = scalar_or_fail(n, file, what);
  const auto v = parse_number(s);
  if (!v) fail(n, file, std::string(what) + ": '" + s + "' is not a number");
  return *v;
}

double read_number(const YAML::Node& n, const std::string& file, std::string_view what, double min, double max) {
  const double v = read_number(n, file, what);
  if (v < min || v > max)
    fail(n, file, std::string(what) + ": value " + n.Scalar() + " out of range [" + fmt_double(min) + ", " +
                      fmt_double(max) + "]");
  return v;
}

std::int64_t read_integer(const YAML::Node& n, const std::string& file, std::string_view what, std::int64_t min,
                          std::int64_t max) {
  const auto s = scalar_or_fail(n, file, what);
  const auto v = parse_integer(s);
  if (!v) fail(n, file, std::string(what) + ": '" + s + "' is not an integer");
  if (*v < min || *v > max)
    fail(n, file, std::string(what) + ": value " + s + " out of range [" + std::to_string(min) + ", " +
                      std::to_string(max) + "]");
  return *v;
}

bool read_bool(const YAML::Node& n, const std::string& file, std::string_view what) {
  const auto s = scalar_or_fail(n, file, what);
  if (s == "true" || s == "yes" || s == "on") return true;
  if (s == "false" || s == "no" || s == "off") return false;
  fail(n, file, std::string(what) + ": '" + s + "' is not true/false");
}

sim::Duration read_duration(const YAML::Node& n, const std::string& file, std::string_view what) {
  const auto s = scalar_or_fail(n, file, what);
  std::string problem;
  const auto d = parse_duration(s, &problem);
  if (!d) fail(n, file, std::string(what) + ": '" + s + "' " + problem);
  return *d;
}

sim::Duration read_period(const YAML::Node& n, const std::string& file, std::string_view what) {
  std::string s = trim(scalar_or_fail(n, file, what));
  for (const auto& [suffix, scale] : {std::pair<const char*, double>{"kHz", 1e3}, {"Hz", 1.0}}) {
    const std::string suf = suffix;
    if (s.size() > suf.size() && s.compare(s.size() - suf.size(), suf.size(), suf) == 0) {
      const auto f = parse_number(s.substr(0, s.size() - suf.size()));
      if (!f || *f <= 0 || *f * scale > 1e6) fail(n, file, std::string(what) + ": '" + s + "' is not a valid rate");
      return sim::from_seconds(1.0 / (*f * scale));
    }
  }
  const auto d = read_duration(n, file, what);
  if (d.count() <= 0) fail(n, file, std::string(what) + ": must be greater than zero");
  return d;
}

std::vector<std::uint8_t> read_bytes(const YAML::Node& n, const std::string& file, std::string_view what) {
  const auto s = scalar_or_fail(n, file, what);
  std::string hex;
  for (char c : s)
    if (c != ' ' && c != '\t') hex += c;
  std::vector<std::uint8_t> out;
  if (hex.size() % 2 != 0) fail(n, file, std::string(what) + ": '" + s + "' is not a sequence of hex bytes");
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    const auto v = parse_integer("0x" + hex.substr(i, 2));
    if (!v) fail(n, file, std::string(what) + ": '" + s + "' is not a sequence of hex bytes");
    out.push_back(static_cast<std::uint8_t>(*v));
  }
  return out;
}

std::vector<std::string> read_string_list(const YAML::Node& n, const std::string& file, std::string_view what) {
  std::vector<std::string> out;
  if (n.IsScalar()) {
    out.push_back(n.Scalar());
    return out;
  }
  if (!n.IsSequence()) fail(n, file, std::string(what) + ": expected a list");
  for (const auto& item : n) out.push_back(read_string(item, file, what));
  return out;
}

}  // namespace sim
