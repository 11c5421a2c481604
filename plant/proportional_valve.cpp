#include "plant/proportional_valve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "plant/equations.h"
#include "plant/orifice_law.h"

namespace plant {
namespace {

constexpr double kLitresPerMinute = 1e-3 / 60.0;

const std::array<ParameterSpec, ProportionalValve::kParamCount> kParams{{
    {"rated_flow", "m^3/s", 30.0 * kLitresPerMinute, 0.0, 1.0, true,
     "flow through one fully open edge at the rated pressure drop (30 L/min = 5e-4)"},
    {"rated_pressure_drop", "Pa", 5e5, 0.0, 1e8, true, "pressure drop per edge at which rated_flow is quoted"},
    {"overlap", "1", 0.2, 0.0, 0.9, false, "positive spool overlap, fraction of stroke before an edge opens"},
    {"current_preload", "A", 0.0, 0.0, 10.0, false, "solenoid current at which the spool starts to move"},
    {"current_full", "A", 1.0, 0.0, 10.0, true, "solenoid current for full spool stroke"},
    {"spool_natural_frequency", "Hz", 20.0, 0.0, 1000.0, true, "natural frequency of the spool dynamics"},
    {"spool_damping", "1", 0.8, 0.0, 10.0, true, "damping ratio of the spool dynamics"},
    {"leakage_coefficient", "m^3/(s Pa)", 1.7e-13, 0.0, 1e-8, false,
     "laminar leakage per edge (1.7e-13 = 0.1 L/min at 100 bar)"},
    {"transition_pressure", "Pa", 1e4, 0.0, 1e6, true, "pressure drop below which the orifice law turns linear"},
    {"stuck", "1", 0.0, 0.0, 1.0, false, "fault: 1 = spool stuck where it is, 0 = free"},
}};
const std::array<ConnectorSpec, 4> kConnectors{{
    {"P", Domain::Fluid, false, "pressure supply"},
    {"T", Domain::Fluid, false, "tank return"},
    {"A", Domain::Fluid, false, "service port A (opened to P by solenoid A)"},
    {"B", Domain::Fluid, false, "service port B (opened to P by solenoid B)"},
}};
const std::array<SignalSpec, ProportionalValve::kSignalCount> kSignals{{
    {"solenoid_a_current", sim::PortDirection::Input, "A", "current in solenoid A (drives the spool towards P->A)", sim::display::mA},
    {"solenoid_b_current", sim::PortDirection::Input, "A", "current in solenoid B (drives the spool towards P->B)", sim::display::mA},
    {"spool_position", sim::PortDirection::Output, "1", "spool position, -1 (full P->B) .. +1 (full P->A)", sim::display::percent},
    {"flow_a", sim::PortDirection::Output, "m^3/s", "flow out of port A into its line", sim::display::l_per_min},
    {"flow_b", sim::PortDirection::Output, "m^3/s", "flow out of port B into its line", sim::display::l_per_min},
}};

std::string check(std::span<const double> v) {
  if (v[ProportionalValve::kCurrentFull] <= v[ProportionalValve::kCurrentPreload])
    return "current_full must be greater than current_preload";
  return {};
}

const ComponentType kType{
    "proportional_valve",
    "4/3 proportional directional valve with two solenoids",
    kParams,
    kConnectors,
    kSignals,
    check,
    make_component<ProportionalValve>,
};

}  // namespace

const ComponentType& ProportionalValve::type_info() { return kType; }

ProportionalValve::ProportionalValve(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  parameters_changed();
}

void ProportionalValve::parameters_changed() {
  kv_ = parameter(kRatedFlow) / std::sqrt(parameter(kRatedPressureDrop));
  if (h_ > 0.0) configure_step(h_);
}

double ProportionalValve::commanded_position(double current_a, double current_b) const {
  const double preload = parameter(kCurrentPreload);
  const double span = parameter(kCurrentFull) - preload;
  auto force = [&](double i) { return std::clamp((std::abs(i) - preload) / span, 0.0, 1.0); };
  return force(current_a) - force(current_b);
}

double ProportionalValve::opening(double s) const {
  const double overlap = parameter(kOverlap);
  if (s < overlap) return 0.0;  // closed (what the clamp below gives), without the division
  return std::clamp((s - overlap) / (1.0 - overlap), 0.0, 1.0);
}

void ProportionalValve::read_inputs() {
  command_ = commanded_position(sanitize_input(in(kSolenoidACurrent)), sanitize_input(in(kSolenoidBCurrent)));
}

void ProportionalValve::configure_step(double h) {
  h_ = h;
  spool_.configure(2.0 * std::numbers::pi * parameter(kSpoolNaturalFrequency), parameter(kSpoolDamping), h);
}

void ProportionalValve::advance(double /*h*/) {
  const double x0 = spool_.position();
  if (parameter(kStuck) >= 0.5) {
    spool_.hold();
  } else {
    spool_.advance(command_);
  }
  const double x1 = spool_.position();
  open_forward_ = 0.5 * (opening(x0) + opening(x1));
  open_reverse_ = 0.5 * (opening(-x0) + opening(-x1));
}

// Inlined into stamp(): four edges per call, two calls per step.
[[gnu::always_inline]] inline void ProportionalValve::stamp_edge(Equations& eq, NodeId a, NodeId b, double dp,
                                                                 double open, const EdgeLaw& law) {
  const double c = law.leakage;
  if (open > 0.0) {
    const auto f = orifice_flow(law.kv * open, dp, law.transition);
    if (eq.mode() != Equations::Mode::Power) {
      // One stamp for both flows of the edge (the energy balance needs them apart).
      eq.flow(a, b, f.q + c * dp, f.dq_ddp + c, EnergyKind::Throttling);
      return;
    }
    eq.flow(a, b, f.q, f.dq_ddp, EnergyKind::Throttling);
  }
  if (c > 0.0) eq.flow(a, b, c * dp, c, EnergyKind::Leakage);
}

void ProportionalValve::stamp(Equations& eq) const {
  const NodeId p = node(kP), t = node(kT), a = node(kA), b = node(kB);
  const double pp = eq.pressure(p), pt = eq.pressure(t), pa = eq.pressure(a), pb = eq.pressure(b);
  const double forward = open_forward_, reverse = open_reverse_;
  const EdgeLaw law{kv_, parameter(kLeakageCoefficient), parameter(kTransitionPressure)};
  stamp_edge(eq, p, a, pp - pa, forward, law);
  stamp_edge(eq, b, t, pb - pt, forward, law);
  stamp_edge(eq, p, b, pp - pb, reverse, law);
  stamp_edge(eq, a, t, pa - pt, reverse, law);
}

[[gnu::always_inline]] inline double ProportionalValve::edge_flow(const CircuitState& state, int from, int to,
                                                                   double open) const {
  const double dp = state.p(node(from)) - state.p(node(to));
  const double metered = open > 0.0 ? orifice_flow(kv_ * open, dp, parameter(kTransitionPressure)).q : 0.0;
  return metered + parameter(kLeakageCoefficient) * dp;
}

void ProportionalValve::publish(const CircuitState& state, double /*dt*/) {
  const double x = spool_.position();
  const double fwd = opening(x), rev = opening(-x);
  out(kSpoolPosition) = x;
  out(kFlowA) = edge_flow(state, kP, kA, fwd) - edge_flow(state, kA, kT, rev);
  out(kFlowB) = edge_flow(state, kP, kB, rev) - edge_flow(state, kB, kT, fwd);
}

}  // namespace plant
