// The scenario's names for the project's one strict YAML reader (sim/yaml_fields.h: MapReader and
// the typed scalars, each throwing a LoadError at the offending node), and the scenario's own
// literal: a scalar kept as the author wrote it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "engine/loading/source_mark.h"
#include "sim/yaml_fields.h"

namespace scenario {

using sim::kMaxDurationSeconds;
using sim::MapReader;
using sim::mark_of;
using sim::parse_duration;
using sim::parse_integer;
using sim::parse_number;
using sim::parse_yaml;
using sim::read_bool;
using sim::read_bytes;
using sim::read_duration;
using sim::read_integer;
using sim::read_name;
using sim::read_number;
using sim::read_period;
using sim::read_string;
using sim::read_string_list;

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
