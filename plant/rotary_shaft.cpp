#include "plant/rotary_shaft.h"

#include <array>

#include "plant/equations.h"
#include "plant/rigid_body_world.h"

namespace plant {
namespace {

const std::array<ParameterSpec, RotaryShaft::kParamCount> kParams{{
    {"inertia", "kg m^2", 0.25, 0.0, 1e6, true, "inertia of shaft and flywheel about the axis"},
    {"viscous_friction", "N m s/rad", 0.01, 0.0, 1e6, false, "viscous bearing friction"},
    {"coulomb_friction", "N m", 0.5, 0.0, 1e6, false, "dry bearing and seal friction (also the breakaway torque)"},
    {"load_torque", "N m", 0.0, -1e6, 1e6, false, "external torque, positive opposing positive rotation"},
    {"initial_angle", "rad", 0.0, -1e9, 1e9, false, "angle at start"},
}};
const std::array<ConnectorSpec, 1> kConnectors{{
    {"flange", Domain::Rotational, true, "coupling for motors (owns the rigid body)"},
}};
const std::array<SignalSpec, RotaryShaft::kSignalCount> kSignals{{
    {"angle", sim::PortDirection::Output, "rad", "shaft angle, unbounded (counts on over many turns)", sim::display::turns},
    {"speed", sim::PortDirection::Output, "rad/s", "shaft speed", sim::display::rpm},
}};

const ComponentType kType{
    "rotary_shaft",
    "shaft with flywheel on an ODE hinge joint",
    kParams,
    kConnectors,
    kSignals,
    nullptr,
    make_component<RotaryShaft>,
};

}  // namespace

const ComponentType& RotaryShaft::type_info() { return kType; }

RotaryShaft::RotaryShaft(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kStamps | kPublishes);
}

void RotaryShaft::create_bodies(RigidBodyWorld& world) { shaft_ = world.add_hinge(parameter(kInitialAngle)); }

void RotaryShaft::add_inertia(std::vector<double>& dof_mass) const {
  dof_mass[static_cast<std::size_t>(shaft_.index)] += parameter(kInertia);
}

void RotaryShaft::stamp(Equations& eq) const {
  const double cv = parameter(kViscousFriction);
  eq.force(shaft_, -cv * eq.velocity(shaft_), -cv, EnergyKind::Friction);
  eq.force(shaft_, -parameter(kLoadTorque), 0.0, EnergyKind::Load);
  const double tc = parameter(kCoulombFriction);
  eq.dry_friction(shaft_, tc, tc);
}

void RotaryShaft::publish(const CircuitState& state, double /*dt*/) {
  out(kAngle) = state.x(shaft_);
  out(kSpeed) = state.v(shaft_);
}

}  // namespace plant
