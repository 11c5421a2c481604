// Hydraulic motor on a shaft: speed from flow and displacement, torque from pressure, and a shaft
// angle that keeps counting.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plant_test_support.h"

namespace plant {
namespace {

using namespace plant::testing;

constexpr double kDisplacement = 16e-6;  // m^3/rev
const double kPerRadian = kDisplacement / (2 * std::numbers::pi);

// A constant flow through the motor (A in, B to tank) turning a shaft with inertia, viscous
// friction and a load torque.
PlantDescription fed_motor(double flow, double volumetric_efficiency, double load_torque, double viscous) {
  PlantDescription d;
  d.add("fluid", "oil");
  d.add("tank", "tank");
  d.add("flow_source", "source", {{"flow", flow}});
  d.add("volume", "line", {{"volume", 1e-4}});
  d.add("hydraulic_motor", "motor",
        {{"displacement", kDisplacement}, {"volumetric_efficiency", volumetric_efficiency}, {"mechanical_efficiency", 0.92}});
  d.add("rotary_shaft", "shaft",
        {{"inertia", 0.01}, {"viscous_friction", viscous}, {"coulomb_friction", 0.0}, {"load_torque", load_torque}});
  d.connect("return", {"tank.port", "source.A", "motor.B"});
  d.connect("fed", {"source.B", "line.port", "motor.A"});
  d.connect("drive", {"motor.shaft", "shaft.flange"});
  return d;
}

TEST(HydraulicMotor, SteadySpeedIsFlowOverDisplacement) {
  // Lossless volumetrically: w = Q / (D / 2 pi). Tolerance 1 % (issue 6).
  const double q = 2e-4;
  Plant p(fed_motor(q, 1.0, 20.0, 0.5));
  run(p, 2.0);
  RecordProperty("speed_error", figure(relative_error(port(p, "shaft.speed"), q / kPerRadian)));
  EXPECT_LT(relative_error(port(p, "shaft.speed"), q / kPerRadian), 0.01);
}

TEST(HydraulicMotor, TorqueIsDisplacementTimesPressureTimesEfficiency) {
  // At steady speed the motor's torque eta_hm D dp / (2 pi) carries the load and the viscous
  // friction; with eta_v = 0.97 the speed is (Q - C_leak dp) / (D / 2 pi), C_leak from eta_v at
  // rated pressure and speed. Tolerance 1 % (issue 6).
  const double q = 2e-4, load = 20.0, viscous = 0.5;
  Plant p(fed_motor(q, 0.97, load, viscous));
  run(p, 2.0);
  const double w = port(p, "shaft.speed");
  const double dp = port(p, "motor.pressure_a") - port(p, "motor.pressure_b");
  const double torque = 0.92 * kPerRadian * dp;
  RecordProperty("torque_error", figure(relative_error(torque, load + viscous * w)));
  EXPECT_LT(relative_error(torque, load + viscous * w), 0.01);
  const double leak = (1 / 0.97 - 1) * kPerRadian * (3000 * 2 * std::numbers::pi / 60) / (350 * kBar);
  RecordProperty("leaky_speed_error", figure(relative_error(w, (q - leak * dp) / kPerRadian)));
  EXPECT_LT(relative_error(w, (q - leak * dp) / kPerRadian), 0.01);
  EXPECT_LT(w, q / kPerRadian) << "leakage must cost speed";
}

TEST(RotaryShaft, AngleKeepsCountingOverManyTurns) {
  // About 400 rad/s for 2 s: more than 100 revolutions. The angle must equal the integrated
  // speed, with no wrap at +-pi or 2 pi.
  Plant p(fed_motor(1e-3, 1.0, 0.0, 0.05));
  double integral = 0.0, previous = 0.0;
  run(p, 2.0, [&](double) {
    const double w = port(p, "shaft.speed");
    integral += 0.5 * (previous + w) * 1e-3;
    previous = w;
  });
  const double angle = port(p, "shaft.angle");
  EXPECT_GT(angle, 100 * 2 * std::numbers::pi);
  EXPECT_LT(relative_error(angle, integral), 1e-3);
}

TEST(RotaryShaft, TurnsBackwardsBelowZeroToo) {
  PlantDescription d = fed_motor(1e-3, 1.0, 0.0, 0.05);
  d.connections[0].ports.back() = parse_port_reference("motor.A");  // feed B, return A
  d.connections[1].ports.back() = parse_port_reference("motor.B");
  Plant p(d);
  run(p, 1.0);
  EXPECT_LT(port(p, "shaft.angle"), -50 * 2 * std::numbers::pi);
}

}  // namespace
}  // namespace plant
