#include "plant/flow_source.h"

#include <array>

#include "plant/equations.h"

namespace plant {
namespace {

const std::array<ParameterSpec, FlowSource::kParamCount> kParams{{
    {"flow", "m^3/s", 0.0, -1.0, 1.0, false, "flow from A to B (negative: B to A)"},
}};
const std::array<ConnectorSpec, 2> kConnectors{{
    {"A", Domain::Fluid, false, "inlet"},
    {"B", Domain::Fluid, false, "outlet"},
}};

const ComponentType kType{
    "flow_source",
    "ideal constant flow source",
    kParams,
    kConnectors,
    {},
    nullptr,
    make_component<FlowSource>,
};

}  // namespace

const ComponentType& FlowSource::type_info() { return kType; }

FlowSource::FlowSource(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kStamps);
}

void FlowSource::stamp(Equations& eq) const { eq.flow(node(kA), node(kB), parameter(kFlow), 0.0, EnergyKind::Supply); }

}  // namespace plant
