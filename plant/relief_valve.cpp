#include "plant/relief_valve.h"

#include <array>
#include <cmath>

#include "plant/equations.h"

namespace plant {
namespace {

const std::array<ParameterSpec, ReliefValve::kParamCount> kParams{{
    {"cracking_pressure", "Pa", 250e5, 0.0, 1e9, false, "pressure drop P->T at which the valve opens"},
    {"pressure_gradient", "Pa s/m^3", 6e8, 0.0, 1e13, true,
     "slope of the p-Q characteristic above cracking (6e8 = 10 bar per 100 L/min)"},
    {"transition_pressure", "Pa", 1e4, 0.0, 1e6, true, "width of the smoothed opening corner"},
}};
const std::array<ConnectorSpec, 2> kConnectors{{
    {"P", Domain::Fluid, false, "protected line"},
    {"T", Domain::Fluid, false, "return to tank"},
}};
const std::array<SignalSpec, ReliefValve::kSignalCount> kSignals{{
    {"flow", sim::PortDirection::Output, "m^3/s", "flow P->T through the valve", sim::display::l_per_min},
}};

const ComponentType kType{
    "relief_valve",
    "pressure relief valve",
    kParams,
    kConnectors,
    kSignals,
    nullptr,
    make_component<ReliefValve>,
};

}  // namespace

const ComponentType& ReliefValve::type_info() { return kType; }

ReliefValve::ReliefValve(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kStamps | kPublishes);
}

double ReliefValve::flow(double dp, double* slope) const {
  const double u = dp - parameter(kCrackingPressure);
  const double d = parameter(kTransitionPressure);
  const double root = std::sqrt(u * u + d * d);
  const double g = parameter(kPressureGradient);
  if (slope != nullptr) *slope = 0.5 * (1.0 + u / root) / g;
  return 0.5 * (u + root) / g;
}

void ReliefValve::stamp(Equations& eq) const {
  double slope = 0.0;
  const double q = flow(eq.pressure(node(kP)) - eq.pressure(node(kT)), &slope);
  eq.flow(node(kP), node(kT), q, slope, EnergyKind::Relief);
}

void ReliefValve::publish(const CircuitState& state, double /*dt*/) {
  out(kFlow) = flow(state.p(node(kP)) - state.p(node(kT)), nullptr);
}

}  // namespace plant
