// Reads a scenario YAML file into a Scenario: syntax, structure, key names, value types and
// ranges. What needs the devices and the plant (device types, ports, object dictionary entries,
// node-IDs) is checked when the scenario is built (world.h). Errors: LoadError `file:line:col`.
#pragma once

#include <string>

#include "engine/loading/scenario.h"

namespace scenario {

Scenario load_scenario_file(const std::string& path);
/// The text of a scenario file (not a FIFO, directory or huge file) and its directory, for
/// relative input paths; throws LoadError.
std::string read_scenario_file(const std::string& path, std::string& dir);
/// `file` names the text in errors; relative input paths resolve against `dir`.
Scenario parse_scenario(const std::string& text, const std::string& file, const std::string& dir);
/// The second half of parse_scenario, after parse_yaml (engine/loading/yaml_fields.h): the
/// scenario from its YAML document. The document's `matrix:` is not read here (ScenarioCases
/// expands it).
Scenario parse_scenario_node(const YAML::Node& root, const std::string& file, const std::string& dir);

}  // namespace scenario
