// The script and fault sections of a scenario: steps of the scripted master and fault injections.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "engine/scenario.h"

namespace scenario {

std::vector<Step> read_script(const YAML::Node& seq, const std::string& file);
std::vector<FaultSpec> read_faults(const YAML::Node& seq, const std::string& file);

/// "0x6040", "0x6040:0", "0x1A00:0x01" → index, sub. Throws at `mark`.
void parse_object_address(const std::string& text, const SourceMark& mark, std::uint16_t& index, std::uint8_t& sub);

}  // namespace scenario
