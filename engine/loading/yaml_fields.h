// Strict reading of scenario YAML: every mapping is read through a MapReader that rejects unknown
// and duplicate keys, and every scalar through a typed parser that checks its range. All errors
// are LoadErrors at the offending node (`file:line:col: reason`).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/time.h"
#include "engine/loading/source_mark.h"

namespace scenario {

SourceMark mark_of(const YAML::Node& node, const std::string& file);

/// A mapping whose keys must all be known: get()/require() mark keys as used, finish() rejects
/// the first key nobody asked for.
class MapReader {
 public:
  /// Throws unless `node` is a mapping; `what` names it in messages ("node 'dsv'", "clock").
  MapReader(const YAML::Node& node, std::string file, std::string what);

  bool has(std::string_view key) const;
  /// The value under `key` (an invalid/undefined node when absent, test with `if (n)`).
  YAML::Node get(std::string_view key);
  YAML::Node require(std::string_view key);
  /// Throws at the first key that get()/require() never asked for.
  void finish() const;

  /// The single key of this mapping among `choices` (e.g. the action of a script step).
  std::string one_of(const std::vector<std::string>& choices);

  SourceMark mark() const { return mark_of(node_, file_); }
  SourceMark key_mark(std::string_view key) const;
  const std::string& file() const { return file_; }
  const std::string& what() const { return what_; }
  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node node_;
  std::string file_;
  std::string what_;
  std::vector<std::string> asked_;
};

// ---- scalars (each throws LoadError at the node) ------------------------------------------------

std::string read_string(const YAML::Node& n, const std::string& file, std::string_view what);
/// An identifier: letters, digits, '_' and '-', starting with a letter or '_'.
std::string read_name(const YAML::Node& n, const std::string& file, std::string_view what);
double read_number(const YAML::Node& n, const std::string& file, std::string_view what);
double read_number(const YAML::Node& n, const std::string& file, std::string_view what, double min, double max);
std::int64_t read_integer(const YAML::Node& n, const std::string& file, std::string_view what, std::int64_t min,
                          std::int64_t max);
bool read_bool(const YAML::Node& n, const std::string& file, std::string_view what);
/// A duration: a number of seconds, or a number with a unit: `250us`, `10ms`, `1.5s`, `2min`.
sim::Duration read_duration(const YAML::Node& n, const std::string& file, std::string_view what);
/// A sampling period from `100Hz` / `2kHz` or a duration.
sim::Duration read_period(const YAML::Node& n, const std::string& file, std::string_view what);
/// Hex bytes "01 2F a0" (spaces optional between pairs).
std::vector<std::uint8_t> read_bytes(const YAML::Node& n, const std::string& file, std::string_view what);
/// A list of names (a sequence, or one scalar).
std::vector<std::string> read_string_list(const YAML::Node& n, const std::string& file, std::string_view what);

// ---- plain text parsers (no YAML; nullopt when malformed) ---------------------------------------

/// Decimal, `0x` hex or `0b` binary integer with optional sign.
std::optional<std::int64_t> parse_integer(std::string_view text);
std::optional<double> parse_number(std::string_view text);
/// The longest duration a scenario may give (sim::Duration counts microseconds in 64 bits).
inline constexpr double kMaxDurationSeconds = 1e9;
/// "10", "2.5s", "500ms", "250us", "1min". When malformed, `problem` (if given) says why, to
/// follow the quoted text: "is not a duration (...)", "is negative (...)", "is out of range (...)".
std::optional<sim::Duration> parse_duration(std::string_view text, std::string* problem = nullptr);

/// A scalar as the scenario author wrote it: integer, real or text (quoted scalars are text).
struct Literal {
  enum class Kind { Integer, Real, Text } kind = Kind::Integer;
  std::int64_t integer = 0;
  double real = 0;
  std::string text;
  SourceMark mark;

  double as_double() const { return kind == Kind::Integer ? static_cast<double>(integer) : real; }
  std::string to_string() const;
};
Literal read_literal(const YAML::Node& n, const std::string& file, std::string_view what);

}  // namespace scenario
