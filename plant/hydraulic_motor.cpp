#include "plant/hydraulic_motor.h"

#include <array>
#include <cmath>
#include <numbers>

#include "plant/equations.h"

namespace plant {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

const std::array<ParameterSpec, HydraulicMotor::kParamCount> kParams{{
    {"displacement", "m^3/rev", 16e-6, 0.0, 1e-2, true, "displacement D per revolution (A2FM 16: 16 cm^3)"},
    {"volumetric_efficiency", "1", 0.97, 0.0, 1.0, true, "eta_v at rated pressure and speed"},
    {"mechanical_efficiency", "1", 0.92, 0.0, 1.0, true, "hydromechanical efficiency eta_hm"},
    {"rated_pressure", "Pa", 350e5, 0.0, 1e9, true, "pressure at which volumetric_efficiency is quoted"},
    {"rated_speed", "rad/s", 3000.0 * kTwoPi / 60.0, 0.0, 1e4, true,
     "speed at which volumetric_efficiency is quoted (3000 rpm = 314.16 rad/s)"},
    {"rotor_inertia", "kg m^2", 4e-4, 0.0, 100.0, false, "inertia of the rotating group, added to the shaft"},
    {"port_volume", "m^3", 8e-6, 0.0, 1.0, false, "internal volume on each side, added to nodes A and B"},
}};
const std::array<ConnectorSpec, 3> kConnectors{{
    {"A", Domain::Fluid, false, "inlet for positive rotation"},
    {"B", Domain::Fluid, false, "outlet for positive rotation"},
    {"shaft", Domain::Rotational, false, "output shaft, coupled rigidly to a rotary_shaft"},
}};
const std::array<SignalSpec, HydraulicMotor::kSignalCount> kSignals{{
    {"pressure_a", sim::PortDirection::Output, "Pa", "pressure at port A", sim::display::bar},
    {"pressure_b", sim::PortDirection::Output, "Pa", "pressure at port B", sim::display::bar},
    {"flow", sim::PortDirection::Output, "m^3/s", "flow into port A (displacement + leakage)", sim::display::l_per_min},
    {"torque", sim::PortDirection::Output, "N m", "hydraulic torque D/(2 pi) (p_A - p_B), before mechanical loss", sim::display::newton_metre},
}};

const ComponentType kType{
    "hydraulic_motor",
    "fixed-displacement hydraulic motor",
    kParams,
    kConnectors,
    kSignals,
    nullptr,
    make_component<HydraulicMotor>,
};

}  // namespace

const ComponentType& HydraulicMotor::type_info() { return kType; }

HydraulicMotor::HydraulicMotor(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kStamps | kPublishes);
  parameters_changed();
}

void HydraulicMotor::parameters_changed() {
  d_rad_ = parameter(kDisplacement) / kTwoPi;
  leak_ = (1.0 / parameter(kVolumetricEfficiency) - 1.0) * d_rad_ * parameter(kRatedSpeed) / parameter(kRatedPressure);
}

void HydraulicMotor::add_volumes(const CircuitState& /*state*/, std::vector<double>& node_volume) const {
  node_volume[static_cast<std::size_t>(node(kA).index)] += parameter(kPortVolume);
  node_volume[static_cast<std::size_t>(node(kB).index)] += parameter(kPortVolume);
}

void HydraulicMotor::add_inertia(std::vector<double>& dof_mass) const {
  dof_mass[static_cast<std::size_t>(dof(kShaft).index)] += parameter(kRotorInertia);
}

void HydraulicMotor::stamp(Equations& eq) const {
  const NodeId a = node(kA), b = node(kB);
  const DofId shaft = dof(kShaft);
  eq.displacement(a, shaft, d_rad_);
  eq.displacement(b, shaft, -d_rad_);
  const double dp = eq.pressure(a) - eq.pressure(b);
  if (leak_ > 0.0) eq.flow(a, b, leak_ * dp, leak_, EnergyKind::Leakage);
  const double loss = (1.0 - parameter(kMechanicalEfficiency)) * std::abs(d_rad_ * dp);
  eq.dry_friction(shaft, loss, loss);
}

void HydraulicMotor::publish(const CircuitState& state, double /*dt*/) {
  const double pa = state.p(node(kA)), pb = state.p(node(kB));
  out(kPressureA) = pa;
  out(kPressureB) = pb;
  out(kFlow) = d_rad_ * state.v(dof(kShaft)) + leak_ * (pa - pb);
  out(kTorque) = d_rad_ * (pa - pb);
}

}  // namespace plant
