// The physics of plant/ behind the engine's PlantModel interface. A scenario's `plant:` section
// is either the plant's own YAML format (docs/plant.md, "YAML format") or the reference plant
// with optional parameter changes:
//   plant:
//     reference: true
//     parameters: {cyl.load_force: 2000, relief.cracking_pressure: 200e5}
#pragma once

#include <memory>
#include <string>

#include <yaml-cpp/yaml.h>

#include "engine/running/plant_model.h"

namespace scenario {

/// Throws LoadError (`file:line:col: reason`) for a section the plant rejects.
std::unique_ptr<PlantModel> make_physics_plant(const YAML::Node& section, const std::string& file);

}  // namespace scenario
