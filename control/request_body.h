// The body of a request to the API: a JSON object read by the scenario's strict reader
// (engine/loading/yaml_fields.h), so an HTTP body and a scenario file are checked by the same code
// and refused for the same mistakes — an unknown or repeated key, a value of the wrong type or out
// of range — each reported as `<body>:line:col: reason` (docs/api.md, "Errors").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/loading/yaml_fields.h"

namespace control {

/// Why a body was refused: answered 400 with `reason`, nothing changed.
struct BodyError {
  std::string reason;
};

class RequestBody {
 public:
  /// `what` names the request in messages ("the SDO write"). Throws BodyError unless `text` is
  /// one JSON object in valid UTF-8.
  RequestBody(const std::string& text, std::string what);

  bool has(std::string_view key) const { return fields_.has(key); }
  /// The raw node under `key` (marks it as read; invalid when absent).
  YAML::Node get(std::string_view key) { return fields_.get(key); }

  std::string text(std::string_view key);
  std::optional<std::string> text_or(std::string_view key);
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi);
  std::optional<std::int64_t> integer_or(std::string_view key, std::int64_t lo, std::int64_t hi);
  double number(std::string_view key);
  std::optional<double> number_or(std::string_view key);
  bool flag_or(std::string_view key, bool fallback);
  /// A value as a scenario writes one: integer, real or text (engine/loading/value_codec.h).
  scenario::Literal literal(std::string_view key);
  /// Hex bytes ("0F00", "0f 00"), between `min` and `max` of them.
  std::vector<std::uint8_t> bytes(std::string_view key, std::size_t min, std::size_t max);
  /// A node named by text, or the one integer `all` stands for (NMT: 0) / null when `null_ok`.
  /// Returns nullopt for `all`/null.
  std::optional<std::string> node_or_all(std::string_view key, bool null_ok);

  /// The text as YAML for a reader of the caller's (a fault: engine/loading/fault_codec.h). Throws
  /// BodyError unless it is one JSON object in valid UTF-8.
  static YAML::Node parse(const std::string& text);

  /// Refuses the first key no one read (a misspelt optional key must not be silently ignored).
  void finish() const;

  /// Where a node of the body was written, for messages of the caller's own.
  std::string at(const YAML::Node& n) const;
  const std::string& file() const { return fields_.file(); }

 private:
  bool present(std::string_view key);
  YAML::Node root_;
  scenario::MapReader fields_;
};

/// Runs `read` and turns the reader's LoadError (`<body>:line:col: reason`) into a BodyError.
template <class F>
auto read_body(F&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const scenario::LoadError& e) {
    throw BodyError{e.what()};
  }
}

}  // namespace control
