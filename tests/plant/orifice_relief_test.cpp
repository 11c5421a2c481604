// Orifice law of the valve's metering edges, and the relief valve holding its setting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "plant/orifice_law.h"
#include "plant_test_support.h"

namespace plant {
namespace {

using namespace plant::testing;

constexpr double kRatedFlow = 30 * kLitresPerMinute;  // per edge at 5 bar
constexpr double kKv = kRatedFlow / 707.1067811865476;  // / sqrt(5e5 Pa)

// A constant flow pushed through the P->A edge of a valve whose spool the currents hold open:
// the node pressure must settle where Kv * a * sqrt(dp) equals the flow.
PlantDescription metered_flow(double flow) {
  PlantDescription d;
  d.add("fluid", "oil");
  d.add("tank", "tank");
  d.add("flow_source", "source", {{"flow", flow}});
  d.add("volume", "line", {{"volume", 1e-4}});
  d.add("volume", "blind", {{"volume", 1e-4}});
  d.add("pressure_sensor", "p");
  d.add("proportional_valve", "valve",
        {{"rated_flow", kRatedFlow}, {"rated_pressure_drop", 5 * kBar}, {"overlap", 0.2}, {"leakage_coefficient", 0.0}});
  d.connect("return", {"tank.port", "source.A", "valve.A", "valve.T"});
  d.connect("supply", {"source.B", "line.port", "p.port", "valve.P"});
  d.connect("blind", {"valve.B", "blind.port"});
  return d;
}

TEST(Orifice, SteadyFlowIsKvTimesOpeningTimesRootOfPressureDrop) {
  // Spool at 0.6 of stroke, overlap 0.2: edge opening a = (0.6 - 0.2) / 0.8 = 0.5.
  // 30 L/min must then pass at dp = (Q / (Kv a))^2 = 20 bar. Tolerance 0.5 % (issue 6).
  const double q = 30 * kLitresPerMinute;
  Plant p(metered_flow(q));
  port(p, "valve.solenoid_a_current") = 0.6;  // current_full 1 A, no preload: spool -> 0.6
  run(p, 0.5);
  ASSERT_NEAR(port(p, "valve.spool_position"), 0.6, 1e-9);
  const double dp = port(p, "p.pressure");
  const double predicted_flow = kKv * 0.5 * std::sqrt(dp);
  RecordProperty("flow_error", figure(relative_error(predicted_flow, q)));
  EXPECT_LT(relative_error(predicted_flow, q), 0.005);
  EXPECT_LT(relative_error(port(p, "valve.flow_a"), q), 0.005);
}

TEST(Orifice, ReverseFlowThroughTheSameEdge) {
  // A at 50 bar, P at 0: oil flows back A->P through the open edge, Q = -Kv a sqrt(dp).
  PlantDescription d;
  d.add("fluid", "oil");
  d.add("tank", "high", {{"pressure", 50 * kBar}});
  d.add("tank", "low");
  d.add("volume", "blind", {{"volume", 1e-4}});
  d.add("proportional_valve", "valve", {{"rated_flow", kRatedFlow}, {"overlap", 0.2}, {"leakage_coefficient", 0.0}});
  d.connect("a", {"high.port", "valve.A"});
  d.connect("p", {"low.port", "valve.P", "valve.T"});
  d.connect("b", {"valve.B", "blind.port"});
  Plant p(d);
  port(p, "valve.solenoid_a_current") = 0.6;
  run(p, 0.5);
  EXPECT_LT(relative_error(port(p, "valve.flow_a"), -kKv * 0.5 * std::sqrt(50 * kBar)), 0.005);
}

TEST(Orifice, RegularisedRootIsSmoothThroughZero) {
  const double k = 1e-6, d = 1e4;
  // Odd, zero at zero, finite slope k/sqrt(d) there, and the square root far from it.
  EXPECT_EQ(orifice_flow(k, 0.0, d).q, 0.0);
  EXPECT_NEAR(orifice_flow(k, 0.0, d).dq_ddp, k / std::sqrt(d), 1e-15);
  EXPECT_DOUBLE_EQ(orifice_flow(k, -3e5, d).q, -orifice_flow(k, 3e5, d).q);
  EXPECT_LT(relative_error(orifice_flow(k, 1e7, d).q, k * std::sqrt(1e7)), 1e-6);
  // The slope matches a finite difference everywhere (the solver's Jacobian relies on it).
  for (double dp : {-2e5, -1e4, -10.0, 0.0, 5e3, 1e6}) {
    const double e = 1e-3 * (std::abs(dp) + d);
    const double numeric = (orifice_flow(k, dp + e, d).q - orifice_flow(k, dp - e, d).q) / (2 * e);
    EXPECT_LT(relative_error(orifice_flow(k, dp, d).dq_ddp, numeric), 1e-5) << dp;
  }
}

PlantDescription relieved_supply(double flow) {
  PlantDescription d;
  d.add("fluid", "oil");
  d.add("tank", "tank");
  d.add("flow_source", "source", {{"flow", flow}});
  d.add("volume", "line", {{"volume", 1e-3}});
  d.add("pressure_sensor", "p");
  d.add("relief_valve", "relief", {{"cracking_pressure", 200 * kBar}, {"pressure_gradient", 6e8}});
  d.connect("return", {"tank.port", "source.A", "relief.T"});
  d.connect("supply", {"source.B", "line.port", "p.port", "relief.P"});
  return d;
}

TEST(ReliefValve, HoldsItsSettingUnderExcessFlow) {
  // Everything the source delivers must go over the relief valve, at cracking pressure plus the
  // characteristic's gradient times the flow: 200 bar + 6e8 Pa s/m^3 * Q. Tolerance 0.5 %.
  double worst = 0.0;
  for (double litres_per_minute : {50.0, 100.0, 200.0}) {
    const double q = litres_per_minute * kLitresPerMinute;
    Plant p(relieved_supply(q));
    run(p, 1.0);
    const double expected = 200 * kBar + 6e8 * q;
    worst = std::max(worst, relative_error(port(p, "p.pressure"), expected));
    EXPECT_LT(relative_error(port(p, "p.pressure"), expected), 0.005) << litres_per_minute << " L/min";
    EXPECT_LT(relative_error(port(p, "relief.flow"), q), 0.005);
  }
  RecordProperty("pressure_error", figure(worst));
}

TEST(ReliefValve, SettingCanBeChangedAtRunTime) {
  Plant p(relieved_supply(100 * kLitresPerMinute));
  run(p, 1.0);
  ASSERT_TRUE(p.set_parameter("relief.cracking_pressure", 150 * kBar));
  run(p, 1.0);
  EXPECT_LT(relative_error(port(p, "p.pressure"), 160 * kBar), 0.005);
}

}  // namespace
}  // namespace plant
