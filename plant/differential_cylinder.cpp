#include "plant/differential_cylinder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "plant/equations.h"
#include "plant/rigid_body_world.h"

namespace plant {
namespace {

const std::array<ParameterSpec, DifferentialCylinder::kParamCount> kParams{{
    {"bore_diameter", "m", 0.063, 0.0, 2.0, true, "piston diameter D"},
    {"rod_diameter", "m", 0.036, 0.0, 2.0, true, "rod diameter d (< D)"},
    {"stroke", "m", 0.5, 0.0, 20.0, true, "stroke between the end stops"},
    {"dead_volume_a", "m^3", 6.2e-5, 0.0, 1.0, true, "cap-side volume at x = 0 (ports, cushion)"},
    {"dead_volume_b", "m^3", 4.2e-5, 0.0, 1.0, true, "rod-side volume at x = stroke"},
    {"mass", "kg", 200.0, 0.0, 1e6, true, "moving mass: piston, rod and load"},
    {"coulomb_friction", "N", 250.0, 0.0, 1e7, false, "seal friction while sliding"},
    {"static_friction", "N", 400.0, 0.0, 1e7, false, "breakaway force (>= coulomb_friction)"},
    {"stribeck_velocity", "m/s", 0.01, 0.0, 10.0, true, "speed over which friction falls from static to Coulomb"},
    {"viscous_friction", "N s/m", 1500.0, 0.0, 1e8, false, "viscous friction coefficient"},
    {"leakage_coefficient", "m^3/(s Pa)", 0.0, 0.0, 1e-8, false, "internal leakage across the piston A->B"},
    {"load_force", "N", 0.0, -1e8, 1e8, false, "external force on the rod, positive opposing extension"},
    {"initial_position", "m", 0.0, 0.0, 20.0, false, "piston position at start (0 = fully retracted)"},
    {"sensor_offset", "m", 0.0, -20.0, 20.0, false, "magnet position minus piston position (sensor mounting)"},
}};
const std::array<ConnectorSpec, 2> kConnectors{{
    {"A", Domain::Fluid, false, "cap-side chamber (extends the rod)"},
    {"B", Domain::Fluid, false, "rod-side chamber (retracts the rod)"},
}};
const std::array<SignalSpec, DifferentialCylinder::kSignalCount> kSignals{{
    {"position", sim::PortDirection::Output, "m", "piston position, 0 = fully retracted", sim::display::mm},
    {"velocity", sim::PortDirection::Output, "m/s", "piston velocity, positive extending", sim::display::mm_per_s},
    {"pressure_a", sim::PortDirection::Output, "Pa", "cap-side chamber pressure", sim::display::bar},
    {"pressure_b", sim::PortDirection::Output, "Pa", "rod-side chamber pressure", sim::display::bar},
    {"magnet_position", sim::PortDirection::Output, "m", "position + sensor_offset, for a linear position sensor", sim::display::mm},
    {"hydraulic_force", sim::PortDirection::Output, "N", "A_A p_A - A_B p_B", sim::display::kilonewton},
}};

std::string check(std::span<const double> v) {
  using C = DifferentialCylinder;
  if (v[C::kRodDiameter] >= v[C::kBoreDiameter]) return "rod_diameter must be smaller than bore_diameter";
  if (v[C::kInitialPosition] > v[C::kStroke]) return "initial_position must lie within [0, stroke]";
  if (v[C::kStaticFriction] < v[C::kCoulombFriction]) return "static_friction must be >= coulomb_friction";
  return {};
}

const ComponentType kType{
    "differential_cylinder",
    "single-rod double-acting cylinder, rod and load on an ODE slider with end stops",
    kParams,
    kConnectors,
    kSignals,
    check,
    make_component<DifferentialCylinder>,
};

double circle(double d) { return std::numbers::pi / 4.0 * d * d; }

}  // namespace

const ComponentType& DifferentialCylinder::type_info() { return kType; }

DifferentialCylinder::DifferentialCylinder(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kStamps | kPublishes);
  parameters_changed();
}

void DifferentialCylinder::parameters_changed() {
  area_a_ = circle(parameter(kBoreDiameter));
  area_b_ = area_a_ - circle(parameter(kRodDiameter));
  if (world_ != nullptr) world_->set_limits(rod_, 0.0, parameter(kStroke));
}

void DifferentialCylinder::create_bodies(RigidBodyWorld& world) {
  world_ = &world;
  rod_ = world.add_slider(0.0, parameter(kStroke), parameter(kInitialPosition));
}

void DifferentialCylinder::add_volumes(const CircuitState& state, std::vector<double>& node_volume) const {
  const double x = std::clamp(state.x(rod_), 0.0, parameter(kStroke));
  node_volume[static_cast<std::size_t>(node(kA).index)] += parameter(kDeadVolumeA) + area_a_ * x;
  node_volume[static_cast<std::size_t>(node(kB).index)] += parameter(kDeadVolumeB) + area_b_ * (parameter(kStroke) - x);
}

void DifferentialCylinder::add_inertia(std::vector<double>& dof_mass) const {
  dof_mass[static_cast<std::size_t>(rod_.index)] += parameter(kMass);
}

void DifferentialCylinder::stamp(Equations& eq) const {
  const NodeId a = node(kA), b = node(kB);
  eq.displacement(a, rod_, area_a_);
  eq.displacement(b, rod_, -area_b_);
  const double leak = parameter(kLeakageCoefficient);
  if (leak > 0.0) eq.flow(a, b, leak * (eq.pressure(a) - eq.pressure(b)), leak, EnergyKind::Leakage);
  const double v = eq.velocity(rod_);
  const double cv = parameter(kViscousFriction);
  eq.force(rod_, -cv * v, -cv, EnergyKind::Friction);
  eq.force(rod_, -parameter(kLoadForce), 0.0, EnergyKind::Load);
  if (eq.wants_jacobian()) {  // dry friction is recorded once per step, at its start
    const double fc = parameter(kCoulombFriction), fs = parameter(kStaticFriction);
    const double s = v / parameter(kStribeckVelocity);
    // (at rest, exp(-0) = 1 without the call: a resting rod is common)
    eq.dry_friction(rod_, fs, fc + (fs - fc) * (s == 0.0 ? 1.0 : std::exp(-s * s)));
  }
}

void DifferentialCylinder::publish(const CircuitState& state, double /*dt*/) {
  const double x = state.x(rod_);
  const double pa = state.p(node(kA)), pb = state.p(node(kB));
  out(kPosition) = x;
  out(kVelocity) = state.v(rod_);
  out(kPressureA) = pa;
  out(kPressureB) = pb;
  out(kMagnetPosition) = x + parameter(kSensorOffset);
  out(kHydraulicForce) = area_a_ * pa - area_b_ * pb;
}

}  // namespace plant
