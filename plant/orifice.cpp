#include "plant/orifice.h"

#include <array>
#include <cmath>
#include <numbers>

#include "plant/equations.h"
#include "plant/fluid.h"
#include "plant/orifice_law.h"

namespace plant {
namespace {

const std::array<ParameterSpec, Orifice::kParamCount> kParams{{
    {"diameter", "m", 1e-3, 0.0, 0.1, true, "bore of the orifice"},
    {"discharge_coefficient", "1", 0.7, 0.0, 1.0, true, "Cd of a sharp-edged orifice (0.6-0.7)"},
    {"transition_pressure", "Pa", 1e4, 0.0, 1e6, true, "pressure drop below which the law turns linear"},
}};
const std::array<ConnectorSpec, 2> kConnectors{{
    {"A", Domain::Fluid, false, "one side"},
    {"B", Domain::Fluid, false, "other side"},
}};
const std::array<SignalSpec, Orifice::kSignalCount> kSignals{{
    {"flow", sim::PortDirection::Output, "m^3/s", "flow from A to B", sim::display::l_per_min},
}};

const ComponentType kType{
    "orifice",
    "fixed sharp-edged orifice (throttle)",
    kParams,
    kConnectors,
    kSignals,
    nullptr,
    make_component<Orifice>,
};

}  // namespace

const ComponentType& Orifice::type_info() { return kType; }

Orifice::Orifice(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kStamps | kPublishes);
}

double Orifice::flow_coefficient(double density) const {
  const double d = parameter(kDiameter);
  const double area = std::numbers::pi / 4.0 * d * d;
  return parameter(kDischargeCoefficient) * area * std::sqrt(2.0 / density);
}

void Orifice::stamp(Equations& eq) const {
  const double k = flow_coefficient(eq.fluid().density());
  const auto f = orifice_flow(k, eq.pressure(node(kA)) - eq.pressure(node(kB)), parameter(kTransitionPressure));
  eq.flow(node(kA), node(kB), f.q, f.dq_ddp, EnergyKind::Throttling);
}

void Orifice::publish(const CircuitState& state, double /*dt*/) {
  const double k = flow_coefficient(state.fluid->density());
  out(kFlow) = orifice_flow(k, state.p(node(kA)) - state.p(node(kB)), parameter(kTransitionPressure)).q;
}

}  // namespace plant
