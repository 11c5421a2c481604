// The plant description as YAML: the `plant:` section of a scenario file (docs/plant.md, "YAML
// format"). Every error is reported as `file:line:col: reason` (1-based line and column).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "plant/plant_description.h"

namespace plant {

/// Builds a description from the mapping under `plant:`; `file` names the source in errors.
/// Throws DescriptionError on a malformed section or an invalid plant (see validate()).
PlantDescription parse_plant_description(const YAML::Node& plant, const std::string& file);

/// Reads a YAML file whose top level has a `plant:` key (syntax errors included as DescriptionError).
PlantDescription load_plant_file(const std::string& path);

/// The description as a `plant:` YAML document that parses back to an equivalent description.
std::string to_yaml(const PlantDescription& description);

}  // namespace plant
