// The project's one strict YAML field reader, used by the plant's descriptions, the engine's
// scenarios and exercises, and the control plane's JSON bodies: every mapping is read through a
// MapReader that rejects unknown keys (listing the known ones) and duplicate keys, and every scalar
// through a typed parser that checks its range. Every error is a sim::DiagnosticError at the
// offending node (`file:line:col: reason`). Its own library (vplant_yaml_fields) beside vplant_sim,
// so only the layers that read YAML link yaml-cpp.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/time.h"
#include "sim/diagnostic.h"

namespace sim {

/// Parses YAML text; a syntax error (or nesting beyond the parser's limit) throws at its position.
YAML::Node parse_yaml(const std::string& text, const std::string& file);

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

// ---- scalars (each throws DiagnosticError at the node) ------------------------------------------------

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

}  // namespace sim
