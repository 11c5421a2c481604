// What a scenario can be built from: the product registry and a plant factory. `vplant run` uses
// default_environment() (every registered product, the physics in plant/); tests add their own
// small products and plants.
#pragma once

#include <functional>
#include <string>

#include "devices/registry.h"
#include "engine/running/plant_model.h"

namespace scenario {

struct Environment {
  std::function<const devices::Product*(const std::string& name)> find_product;
  std::function<std::vector<std::string>()> product_names;  ///< for "unknown device" messages
  PlantFactory make_plant;  ///< empty: scenarios with a `plant:` section are rejected
};

Environment default_environment();

}  // namespace scenario
