// The script and fault sections of a scenario: steps of the scripted master and fault injections.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "engine/loading/scenario.h"
#include "engine/loading/yaml_fields.h"

namespace scenario {

std::vector<Step> read_script(const YAML::Node& seq, const std::string& file);
std::vector<FaultSpec> read_faults(const YAML::Node& seq, const std::string& file);

/// The mapping of a condition (`signal` and one of above, below, between, outside, value +
/// tolerance); the caller finishes `r`.
Condition read_condition(MapReader& r, const std::string& file);
/// id / mask / extended and, when `data_key` is given, the data pattern under it.
FramePattern read_pattern(MapReader& r, const std::string& file, const char* data_key);

/// "0x6040", "0x6040:0", "0x1A00:0x01" → index, sub. Throws at `mark`.
void parse_object_address(const std::string& text, const SourceMark& mark, std::uint16_t& index, std::uint8_t& sub);

}  // namespace scenario
