#include "engine/running/environment.h"

#ifdef VPLANT_HAVE_PLANT
#include "engine/running/plant_adapter.h"
#endif

namespace scenario {

Environment default_environment() {
  Environment env;
  env.find_product = [](const std::string& name) { return devices::find_product(name); };
  env.product_names = [] {
    std::vector<std::string> names;
    for (const auto& p : devices::products()) names.push_back(p.name);
    return names;
  };
#ifdef VPLANT_HAVE_PLANT
  env.make_plant = make_physics_plant;
#endif
  return env;
}

}  // namespace scenario
