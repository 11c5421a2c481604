#include "plant/reference_plant.h"

namespace plant {

// Values are written as the SI numbers the YAML file carries, so both spell the same doubles;
// docs/plant.md gives each one's source.
PlantDescription reference_plant_description() {
  PlantDescription d;
  d.solver.max_step = 1e-3;

  d.add("fluid", "oil",
        {{"density", 870.0},         // HLP 46 mineral oil
         {"bulk_modulus", 1.4e9},    // effective, with hoses (14 000 bar)
         {"air_fraction", 0.0},
         {"polytropic_index", 1.4},
         {"atmospheric_pressure", 101325.0},
         {"vapour_pressure", 1000.0}});
  d.add("tank", "tank", {{"pressure", 0.0}});
  d.add("axial_piston_pump", "pump",
        {{"displacement", 71e-6},                 // A4VSO 71: 71 cm^3/rev
         {"drive_speed", 157.07963267948966},     // 1500 rpm electric motor
         {"volumetric_efficiency", 0.96},
         {"hydromechanical_efficiency", 0.95},
         {"rated_pressure", 350e5},
         {"alpha_min", 0.0},                      // open circuit: no over-centre
         {"alpha_max", 1.0},
         {"stroke_time", 0.1},                    // HS4 control, full stroke at full pilot opening
         {"pilot_natural_frequency", 60.0},
         {"pilot_damping", 0.7},
         {"pilot_zero_offset", 0.0},
         {"lvdt_gain", 1.0},
         {"lvdt_offset", 0.0},
         {"initial_swivel_angle", 0.0}});
  d.add("relief_valve", "relief",
        {{"cracking_pressure", 250e5},
         {"pressure_gradient", 6e8},   // 10 bar per 100 L/min
         {"transition_pressure", 1e4}});
  d.add("volume", "supply_line", {{"volume", 1.5e-3}});
  d.add("pressure_sensor", "p_supply", {{"time_constant", 1e-3}});
  d.add("proportional_valve", "valve_cyl",
        {{"rated_flow", 5e-4},          // NG6: 30 L/min per edge at 5 bar
         {"rated_pressure_drop", 5e5},
         {"overlap", 0.2},
         {"current_preload", 0.128},    // matched to the DSV's default Imin/Imax, 256/768 mA
         {"current_full", 0.768},
         {"spool_natural_frequency", 20.0},
         {"spool_damping", 0.8},
         {"leakage_coefficient", 1.7e-13},
         {"transition_pressure", 1e4},
         {"stuck", 0.0}});
  d.add("volume", "cyl_line_a", {{"volume", 2e-4}});
  d.add("volume", "cyl_line_b", {{"volume", 2e-4}});
  d.add("differential_cylinder", "cyl",
        {{"bore_diameter", 0.063},
         {"rod_diameter", 0.036},
         {"stroke", 0.5},
         {"dead_volume_a", 62e-6},
         {"dead_volume_b", 42e-6},
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
        {{"rated_flow", 4e-4},          // NG6: 24 L/min per edge at 5 bar
         {"rated_pressure_drop", 5e5},
         {"overlap", 0.2},
         {"current_preload", 0.0},      // matched to the MD2's default Imin/Imax, 0.2/1.0 A
         {"current_full", 1.0},
         {"spool_natural_frequency", 20.0},
         {"spool_damping", 0.8},
         {"leakage_coefficient", 1.7e-13},
         {"transition_pressure", 1e4},
         {"stuck", 0.0}});
  d.add("volume", "motor_line_a", {{"volume", 1e-4}});
  d.add("volume", "motor_line_b", {{"volume", 1e-4}});
  d.add("hydraulic_motor", "motor",
        {{"displacement", 16e-6},       // A2FM 16
         {"volumetric_efficiency", 0.97},
         {"mechanical_efficiency", 0.92},
         {"rated_pressure", 350e5},
         {"rated_speed", 314.1592653589793},  // 3000 rpm
         {"rotor_inertia", 4e-4},
         {"port_volume", 8e-6}});
  d.add("rotary_shaft", "shaft",
        {{"inertia", 0.25},             // steel flywheel 300 mm x 40 mm, plus shaft
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
