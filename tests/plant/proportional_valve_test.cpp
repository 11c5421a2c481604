// The 4/3 proportional valve's spool: current-force characteristic, second-order dynamics, the
// stuck-spool fault.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "plant_test_support.h"

namespace plant {
namespace {

using namespace plant::testing;

PlantDescription valve_bench(double preload, double full) {
  PlantDescription d;
  d.add("fluid", "oil");
  d.add("tank", "supply", {{"pressure", 100 * kBar}});
  d.add("tank", "tank");
  d.add("volume", "a", {{"volume", 1e-4}});
  d.add("volume", "b", {{"volume", 1e-4}});
  d.add("proportional_valve", "valve",
        {{"current_preload", preload}, {"current_full", full}, {"spool_natural_frequency", 20.0}, {"spool_damping", 0.8}});
  d.connect("p", {"supply.port", "valve.P"});
  d.connect("t", {"tank.port", "valve.T"});
  d.connect("a", {"valve.A", "a.port"});
  d.connect("b", {"valve.B", "b.port"});
  return d;
}

TEST(ProportionalValve, SpoolSettlesWhereTheCurrentsPutIt) {
  // Linear above the preload, saturating at full stroke; B pushes the other way.
  Plant p(valve_bench(0.128, 0.768));
  struct Case {
    double ia, ib, x;
  };
  for (const Case c : {Case{0.448, 0.0, 0.5}, Case{0.0, 0.768, -1.0}, Case{1.2, 0.0, 1.0}, Case{0.1, 0.0, 0.0},
                       Case{0.448, 0.288, 0.25}}) {
    port(p, "valve.solenoid_a_current") = c.ia;
    port(p, "valve.solenoid_b_current") = c.ib;
    run(p, 0.5);
    EXPECT_NEAR(port(p, "valve.spool_position"), c.x, 1e-6) << c.ia << " A / " << c.ib << " A";
  }
}

TEST(ProportionalValve, SpoolStepResponseIsTheSecondOrderOne) {
  // x(t) = u (1 - e^(-z w t) (cos wd t + z/sqrt(1-z^2) sin wd t)), w = 2 pi 20 Hz, z = 0.8;
  // checked at every tick to 0.5 % of the step.
  Plant p(valve_bench(0.0, 1.0));
  const double w = 2 * std::numbers::pi * 20.0, z = 0.8, wd = w * std::sqrt(1 - z * z), u = 0.7;
  port(p, "valve.solenoid_a_current") = u;
  double worst = 0.0;
  for (int k = 1; k <= 150; ++k) {
    run(p, 0.001);
    const double t = k * 0.001;
    const double x = u * (1 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1 - z * z) * std::sin(wd * t)));
    worst = std::max(worst, std::abs(port(p, "valve.spool_position") - x) / u);
  }
  RecordProperty("worst_error", figure(worst));
  EXPECT_LT(worst, 0.005);
}

TEST(ProportionalValve, StuckSpoolIgnoresTheCurrents) {
  Plant p(valve_bench(0.0, 1.0));
  port(p, "valve.solenoid_a_current") = 0.5;
  run(p, 0.5);
  ASSERT_TRUE(p.set_parameter("valve.stuck", 1.0));
  port(p, "valve.solenoid_a_current") = 0.0;
  port(p, "valve.solenoid_b_current") = 1.0;
  run(p, 0.5);
  EXPECT_NEAR(port(p, "valve.spool_position"), 0.5, 1e-9);
  EXPECT_GT(port(p, "valve.flow_a"), 0.0) << "a stuck-open valve keeps metering";
  ASSERT_TRUE(p.set_parameter("valve.stuck", 0.0));
  run(p, 0.5);
  EXPECT_NEAR(port(p, "valve.spool_position"), -1.0, 1e-6);
}

TEST(ProportionalValve, NonFiniteCurrentCountsAsZero) {
  Plant p(valve_bench(0.0, 1.0));
  port(p, "valve.solenoid_a_current") = std::nan("");
  run(p, 0.2);
  EXPECT_EQ(port(p, "valve.spool_position"), 0.0);
  EXPECT_TRUE(std::isfinite(port(p, "valve.flow_a")));
}

}  // namespace
}  // namespace plant
