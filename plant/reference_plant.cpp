#include "plant/reference_plant.h"

#include <numbers>

namespace plant {
namespace {

constexpr double kLitresPerMinute = 1e-3 / 60.0;
constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;
constexpr double kBar = 1e5;
constexpr double kLitre = 1e-3;
constexpr double kCubicCentimetre = 1e-6;

}  // namespace

PlantDescription reference_plant_description() {
  PlantDescription d;
  d.solver.max_step = 1e-3;

  d.add("fluid", "oil",
        {{"density", 870.0},
         {"bulk_modulus", 1.4e9},
         {"air_fraction", 0.0},
         {"polytropic_index", 1.4},
         {"atmospheric_pressure", 101325.0},
         {"vapour_pressure", 1000.0}});
  d.add("tank", "tank", {{"pressure", 0.0}});
  d.add("axial_piston_pump", "pump",
        {{"displacement", 71 * kCubicCentimetre},
         {"drive_speed", 1500 * kRpm},
         {"volumetric_efficiency", 0.96},
         {"hydromechanical_efficiency", 0.95},
         {"rated_pressure", 350 * kBar},
         {"alpha_min", 0.0},
         {"alpha_max", 1.0},
         {"stroke_time", 0.1},
         {"pilot_natural_frequency", 60.0},
         {"pilot_damping", 0.7},
         {"pilot_zero_offset", 0.0},
         {"lvdt_gain", 1.0},
         {"lvdt_offset", 0.0},
         {"initial_swivel_angle", 0.0}});
  d.add("relief_valve", "relief",
        {{"cracking_pressure", 250 * kBar},
         {"pressure_gradient", 10 * kBar / (100 * kLitresPerMinute)},
         {"transition_pressure", 0.1 * kBar}});
  d.add("volume", "supply_line", {{"volume", 1.5 * kLitre}});
  d.add("pressure_sensor", "p_supply", {{"time_constant", 0.001}});
  d.add("proportional_valve", "valve_cyl",
        {{"rated_flow", 30 * kLitresPerMinute},
         {"rated_pressure_drop", 5 * kBar},
         {"overlap", 0.2},
         {"current_preload", 0.128},
         {"current_full", 0.768},
         {"spool_natural_frequency", 20.0},
         {"spool_damping", 0.8},
         {"leakage_coefficient", 1.7e-13},
         {"transition_pressure", 0.1 * kBar},
         {"stuck", 0.0}});
  d.add("volume", "cyl_line_a", {{"volume", 0.2 * kLitre}});
  d.add("volume", "cyl_line_b", {{"volume", 0.2 * kLitre}});
  d.add("differential_cylinder", "cyl",
        {{"bore_diameter", 0.063},
         {"rod_diameter", 0.036},
         {"stroke", 0.5},
         {"dead_volume_a", 62 * kCubicCentimetre},
         {"dead_volume_b", 42 * kCubicCentimetre},
         {"mass", 200.0},
         {"coulomb_friction", 250.0},
         {"static_friction", 400.0},
         {"stribeck_velocity", 0.01},
         {"viscous_friction", 1500.0},
         {"leakage_coefficient", 0.0},
         {"load_force", 0.0},
         {"initial_position", 0.0},
         {"sensor_offset", 0.0}});
  d.add("proportional_valve", "valve_motor",
        {{"rated_flow", 20 * kLitresPerMinute},
         {"rated_pressure_drop", 5 * kBar},
         {"overlap", 0.2},
         {"current_preload", 0.0},
         {"current_full", 1.0},
         {"spool_natural_frequency", 20.0},
         {"spool_damping", 0.8},
         {"leakage_coefficient", 1.7e-13},
         {"transition_pressure", 0.1 * kBar},
         {"stuck", 0.0}});
  d.add("volume", "motor_line_a", {{"volume", 0.1 * kLitre}});
  d.add("volume", "motor_line_b", {{"volume", 0.1 * kLitre}});
  d.add("hydraulic_motor", "motor",
        {{"displacement", 16 * kCubicCentimetre},
         {"volumetric_efficiency", 0.97},
         {"mechanical_efficiency", 0.92},
         {"rated_pressure", 350 * kBar},
         {"rated_speed", 3000 * kRpm},
         {"rotor_inertia", 4e-4},
         {"port_volume", 8 * kCubicCentimetre}});
  d.add("rotary_shaft", "shaft",
        {{"inertia", 0.25},
         {"viscous_friction", 0.01},
         {"coulomb_friction", 0.5},
         {"load_torque", 0.0},
         {"initial_angle", 0.0}});

  d.connect("tank", {"tank.port", "pump.A", "relief.T", "valve_cyl.T", "valve_motor.T"});
  d.connect("supply", {"pump.B", "relief.P", "supply_line.port", "p_supply.port", "valve_cyl.P", "valve_motor.P"});
  d.connect("cyl_a", {"valve_cyl.A", "cyl_line_a.port", "cyl.A"});
  d.connect("cyl_b", {"valve_cyl.B", "cyl_line_b.port", "cyl.B"});
  d.connect("motor_a", {"valve_motor.A", "motor_line_a.port", "motor.A"});
  d.connect("motor_b", {"valve_motor.B", "motor_line_b.port", "motor.B"});
  d.connect("drive", {"motor.shaft", "shaft.flange"});
  return d;
}

}  // namespace plant
