#include "plant/tank.h"

#include <array>

namespace plant {
namespace {

const std::array<ParameterSpec, Tank::kParamCount> kParams{{
    {"pressure", "Pa", 0.0, -1e5, 1e8, false, "gauge pressure held at the port (0 = open tank)"},
}};
const std::array<ConnectorSpec, 1> kConnectors{{
    {"port", Domain::Fluid, false, "the tank's connection; its node is held at `pressure`"},
}};

const ComponentType kType{
    "tank",
    "reservoir: a node held at a fixed pressure",
    kParams,
    kConnectors,
    {},
    nullptr,
    make_component<Tank>,
};

}  // namespace

const ComponentType& Tank::type_info() { return kType; }

Tank::Tank(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(0u);
}

void Tank::fix_pressures(CircuitState& state) const {
  state.pressure[static_cast<std::size_t>(node(kPort).index)] = parameter(kPressure);
}

}  // namespace plant
