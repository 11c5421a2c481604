#include "control/request_body.h"

#include <nlohmann/json.hpp>

namespace control {
namespace {

// Messages point into the body as a scenario's point into its file.
const std::string kBodyName = "<body>";

scenario::MapReader reader_of(const YAML::Node& root, std::string what) {
  return read_body([&] { return scenario::MapReader(root, kBodyName, std::move(what)); });
}

}  // namespace

YAML::Node RequestBody::parse(const std::string& text) {
  // JSON first: its grammar and valid UTF-8 (YAML would take `{a: 1}` or a stray tab); then the
  // same text as YAML, which JSON is a subset of, for the reader and its line:col marks.
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) throw BodyError{"malformed JSON body"};
  if (!j.is_object()) throw BodyError{"the body must be a JSON object"};
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw BodyError{"malformed JSON body (" + e.msg + ")"};
  }
}

RequestBody::RequestBody(const std::string& text, std::string what)
    : root_(parse(text)), fields_(reader_of(root_, std::move(what))) {}

void RequestBody::finish() const {
  read_body([&] { fields_.finish(); });
}

std::string RequestBody::at(const YAML::Node& n) const { return scenario::mark_of(n, file()).to_string(); }

std::string RequestBody::text(std::string_view key) {
  return read_body([&] { return scenario::read_string(fields_.require(key), file(), key); });
}

// The optional readers ask for their key even when it is absent, so finish() names it among the
// known keys of a misspelt one.
bool RequestBody::present(std::string_view key) { return fields_.get(key).IsDefined(); }

std::optional<std::string> RequestBody::text_or(std::string_view key) {
  if (!present(key)) return std::nullopt;
  return text(key);
}

std::int64_t RequestBody::integer(std::string_view key, std::int64_t lo, std::int64_t hi) {
  return read_body([&] { return scenario::read_integer(fields_.require(key), file(), key, lo, hi); });
}

std::optional<std::int64_t> RequestBody::integer_or(std::string_view key, std::int64_t lo, std::int64_t hi) {
  if (!present(key)) return std::nullopt;
  return integer(key, lo, hi);
}

double RequestBody::number(std::string_view key) {
  return read_body([&] { return scenario::read_number(fields_.require(key), file(), key); });
}

std::optional<double> RequestBody::number_or(std::string_view key) {
  if (!present(key)) return std::nullopt;
  return number(key);
}

bool RequestBody::flag_or(std::string_view key, bool fallback) {
  if (!present(key)) return fallback;
  return read_body([&] { return scenario::read_bool(fields_.require(key), file(), key); });
}

scenario::Literal RequestBody::literal(std::string_view key) {
  return read_body([&] { return scenario::read_literal(fields_.require(key), file(), key); });
}

std::vector<std::uint8_t> RequestBody::bytes(std::string_view key, std::size_t min, std::size_t max) {
  return read_body([&] {
    const auto n = fields_.require(key);
    auto out = scenario::read_bytes(n, file(), key);
    if (out.size() < min || out.size() > max)
      throw scenario::LoadError(scenario::mark_of(n, file()), std::string(key) + ": " + std::to_string(out.size()) +
                                                                  " bytes, expected " + std::to_string(min) + ".." +
                                                                  std::to_string(max));
    return out;
  });
}

std::optional<std::string> RequestBody::node_or_all(std::string_view key, bool null_ok) {
  return read_body([&]() -> std::optional<std::string> {
    const auto n = fields_.require(key);
    const std::string expected = std::string(key) + ": a node's name or " + (null_ok ? "null" : "0");
    if (null_ok && n.IsNull()) return std::nullopt;
    if (!n.IsScalar()) throw scenario::LoadError(scenario::mark_of(n, file()), expected);
    if (n.Tag() != "!" && !null_ok && n.Scalar() == "0") return std::nullopt;
    if (n.Tag() != "!") throw scenario::LoadError(scenario::mark_of(n, file()), expected);
    return n.Scalar();
  });
}

}  // namespace control
