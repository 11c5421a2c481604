// Fluid and volume: a closed volume fed by a constant flow builds pressure at beta*Q/V.
#include <gtest/gtest.h>

#include <cmath>

#include "plant/fluid.h"
#include "plant_test_support.h"

namespace plant {
namespace {

using namespace plant::testing;

PlantDescription fed_volume(double flow, double volume, double air_fraction, double initial_pressure) {
  PlantDescription d;
  d.solver.max_step = 1e-3;
  d.add("fluid", "oil", {{"bulk_modulus", 1.4e9}, {"air_fraction", air_fraction}});
  d.add("tank", "tank");
  d.add("flow_source", "source", {{"flow", flow}});
  d.add("volume", "chamber", {{"volume", volume}});
  d.add("pressure_sensor", "p");
  d.connect("return", {"tank.port", "source.A"});
  d.connect("closed", {"source.B", "chamber.port", "p.port"}, initial_pressure);
  return d;
}

TEST(FluidVolume, PressureSlopeIsBetaTimesFlowOverVolume) {
  // 6 L/min into 1 L of air-free oil: 1400 bar/s. Tolerance 0.5 % (issue 6).
  const double q = 1e-4, v = 1e-3, beta = 1.4e9;
  Plant p(fed_volume(q, v, 0.0, 0.0));
  run(p, 0.005);
  const double p0 = port(p, "p.pressure");
  run(p, 0.020);
  const double slope = (port(p, "p.pressure") - p0) / 0.020;
  RecordProperty("slope_error", figure(relative_error(slope, beta * q / v)));
  EXPECT_LT(relative_error(slope, beta * q / v), 0.005);
}

// The effective bulk modulus with entrained air, written out independently of plant/fluid.cpp:
// gas fraction r of the mixture at absolute pressure P, 1/beta = (1-r)/beta_l + r/(k P).
double entrained_air_bulk_modulus(double gauge, double beta_l, double a0, double k, double pa) {
  const double P = gauge + pa;
  const double x = a0 * std::pow(pa / P, 1.0 / k);
  const double r = x / (1.0 - a0 + x);
  return 1.0 / ((1.0 - r) / beta_l + r / (k * P));
}

TEST(FluidVolume, EntrainedAirSoftensTheFluidAtLowPressure) {
  // With 0.5 % air the slope at 5 bar and at 200 bar follows beta(p) of the mixture (0.5 %).
  for (double p_start : {5 * kBar, 200 * kBar}) {
    const double q = 1e-6, v = 1e-3;
    Plant p(fed_volume(q, v, 0.005, p_start));
    run(p, 0.010);
    const double p0 = port(p, "p.pressure");
    run(p, 0.010);
    const double p1 = port(p, "p.pressure");
    const double expected = entrained_air_bulk_modulus(0.5 * (p0 + p1), 1.4e9, 0.005, 1.4, 101325.0) * q / v;
    RecordProperty(p_start < 10 * kBar ? "slope_error_5bar" : "slope_error_200bar",
                   figure(relative_error((p1 - p0) / 0.010, expected)));
    EXPECT_LT(relative_error((p1 - p0) / 0.010, expected), 0.005) << "at " << p_start / kBar << " bar";
  }
  const Fluid oil("oil", {870.0, 1.4e9, 0.005, 1.4, 101325.0, 1000.0});
  EXPECT_LT(oil.bulk_modulus(0.0), 0.05 * 1.4e9);                   // near atmospheric: mostly air
  EXPECT_LT(relative_error(oil.bulk_modulus(300 * kBar), 1.4e9), 0.01);  // compressed: the liquid
}

TEST(FluidVolume, DrainedVolumeCavitatesAtTheVapourPressureAndRefills) {
  // Drawing 1 cm^3/s out of a closed 1 L volume: the pressure falls to the cavitation pressure
  // and stays there (vapour forms); the same volume put back first refills the vapour, then the
  // pressure rises again.
  Plant p(fed_volume(-1e-6, 1e-3, 0.0, 1 * kBar));
  run(p, 1.0);
  const double cavitation = 1000.0 - 101325.0;
  EXPECT_NEAR(port(p, "p.pressure"), cavitation, 1.0);
  ASSERT_TRUE(p.set_parameter("source.flow", +1e-6));
  // Decompressing 1 L from 1 bar to the cavitation pressure released 1e-3/1.4e9 * 2.0 bar = 0.14 cm^3;
  // the other 0.86 cm^3 drawn became vapour, which the inflow must refill first.
  run(p, 0.5);
  EXPECT_NEAR(port(p, "p.pressure"), cavitation, 1.0) << "pressure must stay until the vapour is refilled";
  // After as much fluid went back as was drawn, the volume is where it started: 1 bar.
  run(p, 0.5);
  EXPECT_NEAR(port(p, "p.pressure"), 1 * kBar, 0.01 * kBar);
}

}  // namespace
}  // namespace plant
