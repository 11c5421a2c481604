// Axial-piston pump: delivered flow, swash-plate actuator dynamics, LVDT.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plant_test_support.h"

namespace plant {
namespace {

using namespace plant::testing;

constexpr double kVg = 71e-6;                                   // m^3/rev
constexpr double kSpeed = 1500 * 2 * std::numbers::pi / 60.0;  // rad/s
constexpr double kRevPerSecond = 1500 / 60.0;

// The pump delivering into a line held near 350 bar by a relief valve.
PlantDescription pump_into_relief(double alpha, double cracking) {
  PlantDescription d;
  d.add("fluid", "oil");
  d.add("tank", "tank");
  d.add("axial_piston_pump", "pump",
        {{"displacement", kVg},
         {"drive_speed", kSpeed},
         {"volumetric_efficiency", 0.96},
         {"rated_pressure", 350 * kBar},
         {"initial_swivel_angle", alpha}});
  d.add("volume", "line", {{"volume", 1e-3}});
  d.add("relief_valve", "relief", {{"cracking_pressure", cracking}, {"pressure_gradient", 6e8}});
  d.connect("suction", {"tank.port", "pump.A", "relief.T"});
  d.connect("pressure", {"pump.B", "line.port", "relief.P"});
  return d;
}

TEST(AxialPistonPump, DeliversDisplacementTimesAngleTimesSpeedTimesVolumetricEfficiency) {
  // Full displacement at rated pressure: Q = Vg n eta_v (catalogue definition). The relief valve
  // is set so the line sits at 350 bar: 340 bar + 6e8 Pa s/m^3 * 1.7e-3 m^3/s. Tolerance 0.5 %.
  Plant p(pump_into_relief(1.0, 350 * kBar - 6e8 * kVg * kRevPerSecond * 0.96));
  run(p, 1.0);
  const double pressure = port(p, "pump.pressure_b");
  ASSERT_LT(relative_error(pressure, 350 * kBar), 0.001);
  const double expected = kVg * 1.0 * kRevPerSecond * 0.96;
  RecordProperty("flow_error", figure(relative_error(port(p, "relief.flow"), expected)));
  EXPECT_LT(relative_error(port(p, "relief.flow"), expected), 0.005) << "what physically leaves the line";
  EXPECT_LT(relative_error(port(p, "pump.flow"), expected), 0.005);
}

TEST(AxialPistonPump, LeakageIsPressureDrivenNotAngleDriven) {
  // At half displacement and 200 bar: Q = Vg n (alpha - (1 - eta_v) p / p_rated).
  Plant p(pump_into_relief(0.5, 200 * kBar));
  run(p, 1.0);
  const double pressure = port(p, "pump.pressure_b");
  const double expected = kVg * kRevPerSecond * (0.5 - 0.04 * pressure / (350 * kBar));
  EXPECT_LT(relative_error(port(p, "relief.flow"), expected), 0.005);
}

TEST(AxialPistonPump, SwivelActuatorStepResponseMatchesItsSecondOrderParameters) {
  // Pilot spool: second order, w = 2 pi 60 Hz, z = 0.7 (reference defaults); swash plate:
  // d(alpha)/dt = x / t_stroke, t_stroke = 0.1 s. Step u = 0.5 from alpha = 0.2:
  //   x(t) = u (1 - e^(-z w t)(cos wd t + z/sqrt(1-z^2) sin wd t))
  //   alpha(t) = 0.2 + u/t_stroke (t - 2z/w + e^(-z w t)((2z/w) cos wd t + ((2z^2-1)/wd) sin wd t))
  // Checked every tick: spool to 0.5 % of the step, angle to 0.5 % of its travel.
  Plant p(pump_into_relief(0.2, 100 * kBar));
  const double w = 2 * std::numbers::pi * 60.0, z = 0.7, wd = w * std::sqrt(1 - z * z), u = 0.5, ts = 0.1;
  port(p, "pump.pilot_command") = u;
  double worst_x = 0.0, worst_alpha = 0.0, travel = 0.0;
  for (int k = 1; k <= 100; ++k) {
    run(p, 0.001);
    const double t = k * 0.001, e = std::exp(-z * w * t);
    const double x = u * (1 - e * (std::cos(wd * t) + z / std::sqrt(1 - z * z) * std::sin(wd * t)));
    const double integral = t - 2 * z / w + e * (2 * z / w * std::cos(wd * t) + (2 * z * z - 1) / wd * std::sin(wd * t));
    const double alpha = 0.2 + u / ts * integral;
    worst_x = std::max(worst_x, std::abs(port(p, "pump.pilot_spool_position") - x) / u);
    worst_alpha = std::max(worst_alpha, std::abs(port(p, "pump.swivel_angle") - alpha));
    travel = alpha - 0.2;
  }
  worst_alpha /= travel;  // relative to the angle travelled in the window
  RecordProperty("spool_error", figure(worst_x));
  RecordProperty("angle_error", figure(worst_alpha));
  EXPECT_LT(worst_x, 0.005);
  EXPECT_LT(worst_alpha, 0.005);
}

TEST(AxialPistonPump, SwivelRateIsLimitedByTheFullyOpenPilotAndAngleByItsRange) {
  Plant p(pump_into_relief(0.0, 100 * kBar));
  port(p, "pump.pilot_command") = 5.0;  // beyond full: clamped to +1
  run(p, 0.02);
  const double a0 = port(p, "pump.swivel_angle");
  run(p, 0.02);
  EXPECT_LT(relative_error((port(p, "pump.swivel_angle") - a0) / 0.02, 1.0 / 0.1), 0.005);
  run(p, 0.2);
  EXPECT_EQ(port(p, "pump.swivel_angle"), 1.0);
  port(p, "pump.pilot_command") = -1.0;
  run(p, 0.3);
  EXPECT_EQ(port(p, "pump.swivel_angle"), 0.0) << "an open-circuit pump stops at alpha_min = 0";
}

TEST(AxialPistonPump, LvdtReadsGainTimesAnglePlusOffset) {
  PlantDescription d = pump_into_relief(0.4, 100 * kBar);
  d.components[2].parameters.push_back({"lvdt_gain", 0.9, {}, {}});
  d.components[2].parameters.push_back({"lvdt_offset", 0.05, {}, {}});
  Plant p(d);
  run(p, 0.01);
  EXPECT_DOUBLE_EQ(port(p, "pump.lvdt"), 0.9 * 0.4 + 0.05);
  EXPECT_DOUBLE_EQ(port(p, "pump.drive_speed"), kSpeed);
}

}  // namespace
}  // namespace plant
