// Reads a scenario YAML file into a Scenario: syntax, structure, key names, value types and
// ranges. What needs the devices and the plant (device types, ports, object dictionary entries,
// node-IDs) is checked when the scenario is built (world.h). Errors: LoadError `file:line:col`.
#pragma once

#include <string>

#include "engine/scenario.h"

namespace scenario {

Scenario load_scenario_file(const std::string& path);
/// `file` names the text in errors; relative input paths resolve against `dir`.
Scenario parse_scenario(const std::string& text, const std::string& file, const std::string& dir);

}  // namespace scenario
