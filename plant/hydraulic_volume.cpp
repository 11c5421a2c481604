#include "plant/hydraulic_volume.h"

#include <array>

namespace plant {
namespace {

const std::array<ParameterSpec, HydraulicVolume::kParamCount> kParams{{
    {"volume", "m^3", 1e-3, 0.0, 10.0, true, "fluid volume (hose: pi/4 d^2 L)"},
}};
const std::array<ConnectorSpec, 1> kConnectors{{
    {"port", Domain::Fluid, false, "the node this volume belongs to"},
}};

const ComponentType kType{
    "volume",
    "lumped fluid volume (hose, pipe, manifold)",
    kParams,
    kConnectors,
    {},
    nullptr,
    make_component<HydraulicVolume>,
};

}  // namespace

const ComponentType& HydraulicVolume::type_info() { return kType; }

HydraulicVolume::HydraulicVolume(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(0u);
}

void HydraulicVolume::add_volumes(const CircuitState& /*state*/, std::vector<double>& node_volume) const {
  node_volume[static_cast<std::size_t>(node(kPort).index)] += parameter(kVolume);
}

}  // namespace plant
