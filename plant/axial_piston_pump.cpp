#include "plant/axial_piston_pump.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "plant/equations.h"

namespace plant {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

const std::array<ParameterSpec, AxialPistonPump::kParamCount> kParams{{
    {"displacement", "m^3/rev", 71e-6, 0.0, 1e-2, true, "maximum displacement Vg_max (A4VSO 71: 71 cm^3)"},
    {"drive_speed", "rad/s", 1500.0 * kTwoPi / 60.0, 0.0, 1000.0, false,
     "speed of the electric drive motor (1500 rpm = 157.08 rad/s)"},
    {"volumetric_efficiency", "1", 0.96, 0.0, 1.0, true, "eta_v at rated pressure and full displacement"},
    {"hydromechanical_efficiency", "1", 0.95, 0.0, 1.0, true, "eta_hm, for the drive torque output"},
    {"rated_pressure", "Pa", 350e5, 0.0, 1e9, true, "pressure at which volumetric_efficiency is quoted"},
    {"alpha_min", "1", 0.0, -1.0, 0.0, false, "lowest swivel angle (0: open-circuit A4VSO, -1: over-centre)"},
    {"alpha_max", "1", 1.0, 0.0, 1.0, true, "highest swivel angle"},
    {"stroke_time", "s", 0.1, 0.0, 10.0, true, "time for alpha 0 -> 1 with the pilot valve fully open"},
    {"pilot_natural_frequency", "Hz", 60.0, 0.0, 1000.0, true, "natural frequency of the pilot spool"},
    {"pilot_damping", "1", 0.7, 0.0, 10.0, true, "damping ratio of the pilot spool"},
    {"pilot_zero_offset", "1", 0.0, -0.5, 0.5, false, "hydraulic zero error of the pilot valve (adds to x)"},
    {"lvdt_gain", "1", 1.0, 0.0, 10.0, true, "swivel-angle sensor: lvdt = gain * alpha + offset"},
    {"lvdt_offset", "1", 0.0, -1.0, 1.0, false, "swivel-angle sensor offset"},
    {"initial_swivel_angle", "1", 0.0, -1.0, 1.0, false, "swivel angle at start"},
}};
const std::array<ConnectorSpec, 2> kConnectors{{
    {"A", Domain::Fluid, false, "inlet for alpha > 0 (suction S of an open-circuit pump)"},
    {"B", Domain::Fluid, false, "outlet for alpha > 0 (pressure port)"},
}};
const std::array<SignalSpec, AxialPistonPump::kSignalCount> kSignals{{
    {"pilot_command", sim::PortDirection::Input, "1",
     "pilot valve command -1..+1 (VT-VPCD valve CMD +-100 %); >0 swivels towards +alpha", sim::display::percent},
    {"swivel_angle", sim::PortDirection::Output, "1", "normalised swivel angle alpha (-1..1)", sim::display::percent},
    {"lvdt", sim::PortDirection::Output, "1", "swivel-angle sensor signal, lvdt_gain * alpha + lvdt_offset", sim::display::percent},
    {"pilot_spool_position", sim::PortDirection::Output, "1", "pilot spool position (-1..1)", sim::display::percent},
    {"pressure_a", sim::PortDirection::Output, "Pa", "pressure at port A", sim::display::bar},
    {"pressure_b", sim::PortDirection::Output, "Pa", "pressure at port B", sim::display::bar},
    {"drive_speed", sim::PortDirection::Output, "rad/s", "drive shaft speed", sim::display::rpm},
    {"flow", sim::PortDirection::Output, "m^3/s", "effective flow delivered out of B (after leakage)", sim::display::l_per_min},
    {"drive_torque", sim::PortDirection::Output, "N m", "torque the drive supplies, Vg alpha dp / (2 pi eta_hm)", sim::display::newton_metre},
}};

std::string check(std::span<const double> v) {
  const double a0 = v[AxialPistonPump::kInitialSwivelAngle];
  if (a0 < v[AxialPistonPump::kAlphaMin] || a0 > v[AxialPistonPump::kAlphaMax])
    return "initial_swivel_angle must lie within [alpha_min, alpha_max]";
  return {};
}

const ComponentType kType{
    "axial_piston_pump",
    "variable axial-piston pump with pilot-operated swash plate",
    kParams,
    kConnectors,
    kSignals,
    check,
    make_component<AxialPistonPump>,
};

}  // namespace

const ComponentType& AxialPistonPump::type_info() { return kType; }

AxialPistonPump::AxialPistonPump(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  alpha_ = alpha_mid_ = parameter(kInitialSwivelAngle);
  parameters_changed();
}

void AxialPistonPump::parameters_changed() {
  leak_ = (1.0 - parameter(kVolumetricEfficiency)) * geometric_flow(1.0) / parameter(kRatedPressure);
  alpha_ = std::clamp(alpha_, parameter(kAlphaMin), parameter(kAlphaMax));
  if (h_ > 0.0) configure_step(h_);
}

double AxialPistonPump::geometric_flow(double alpha) const {
  return parameter(kDisplacement) / kTwoPi * alpha * parameter(kDriveSpeed);
}

void AxialPistonPump::read_inputs() { command_ = std::clamp(sanitize_input(in(kPilotCommand)), -1.0, 1.0); }

void AxialPistonPump::configure_step(double h) {
  h_ = h;
  pilot_.configure(kTwoPi * parameter(kPilotNaturalFrequency), parameter(kPilotDamping), h);
}

void AxialPistonPump::advance(double h) {
  pilot_.advance(command_);
  const double alpha0 = alpha_;
  const double travel = (pilot_.last_integral() + parameter(kPilotZeroOffset) * h) / parameter(kStrokeTime);
  alpha_ = std::clamp(alpha_ + travel, parameter(kAlphaMin), parameter(kAlphaMax));
  alpha_mid_ = 0.5 * (alpha0 + alpha_);
}

void AxialPistonPump::stamp(Equations& eq) const {
  const NodeId a = node(kA), b = node(kB);
  eq.flow(a, b, geometric_flow(alpha_mid_), 0.0, EnergyKind::Supply);
  eq.flow(b, a, leak_ * (eq.pressure(b) - eq.pressure(a)), leak_, EnergyKind::PumpLeakage);
}

void AxialPistonPump::publish(const CircuitState& state, double /*dt*/) {
  const double pa = state.p(node(kA)), pb = state.p(node(kB));
  out(kSwivelAngle) = alpha_;
  out(kLvdt) = parameter(kLvdtGain) * alpha_ + parameter(kLvdtOffset);
  out(kPilotSpoolPosition) = pilot_.position();
  out(kPressureA) = pa;
  out(kPressureB) = pb;
  out(kDriveSpeedOut) = parameter(kDriveSpeed);
  out(kFlow) = geometric_flow(alpha_) - leak_ * (pb - pa);
  out(kDriveTorque) = parameter(kDisplacement) / kTwoPi * alpha_ * (pb - pa) / parameter(kHydromechanicalEfficiency);
}

}  // namespace plant
