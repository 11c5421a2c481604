// The stand-in plant on its own: analytic checks of its equations (digest §4.8).
#include "devices/vtvpcd/builtin_pump_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace vtvpcd;

TEST(BuiltinPumpModel, SwashPlateIntegratesTheSpoolOpening) {
  BuiltinPlantSettings s;
  BuiltinPumpModel m(s, PumpType::A4VSO);
  m.step(100.0, 0.1);  // spool lag 5 ms, then 1000 %/s
  EXPECT_NEAR(m.spool_pct(), 100.0, 1e-6);
  const double expected = (0.1 - 0.005 * (1.0 - std::exp(-0.1 / 0.005))) * 1000.0;
  EXPECT_NEAR(m.alpha_pct(), expected, 1.0);
  m.step(100.0, 1.0);
  EXPECT_DOUBLE_EQ(m.alpha_pct(), 100.0);  // end stop
  m.step(-25.0, 1.0);
  EXPECT_DOUBLE_EQ(m.alpha_pct(), 0.0);    // A4VSO: nothing below 0
}

TEST(BuiltinPumpModel, SteadyPressureBalancesFlow) {
  BuiltinPlantSettings s;
  BuiltinPumpModel m(s, PumpType::A4VSO);
  m.step(100.0, 0.2);
  for (int i = 0; i < 3000; ++i) m.step(0.0, 0.001);
  // Q = 187.5 L/min = 10 sqrt(p) + 0.02 p  ->  p = 327.4 bar.
  const double p = m.p_b_bar();
  EXPECT_NEAR(10.0 * std::sqrt(p) + 0.02 * p, 187.5, 0.05);
  EXPECT_NEAR(p, 327.4, 0.5);
  EXPECT_DOUBLE_EQ(m.p_a_bar(), 0.0);
  EXPECT_NEAR(m.flow_l_min(), 187.5, 1e-9);
}

TEST(BuiltinPumpModel, PressureBuildUpRate) {
  BuiltinPlantSettings s;
  s.k_load = 0;
  s.c_leak = 0;
  s.oil_volume_l = 10000;  // slow enough to watch: beta/V * Q / 60 = 1.4 * 187.5 / 60 = 4.375 bar/s
  BuiltinPumpModel m(s, PumpType::A4VSO);
  m.step(100.0, 0.2);  // full angle
  const double p0 = m.p_b_bar();
  m.step(0.0, 0.001);  // the spool closes within the step; the plate stays at 100 %
  EXPECT_DOUBLE_EQ(m.alpha_pct(), 100.0);
  EXPECT_NEAR((m.p_b_bar() - p0) / 0.001, 4.375, 1e-6);
}

TEST(BuiltinPumpModel, ReliefValveLimitsADeadHeadedPump) {
  BuiltinPlantSettings s;
  s.k_load = 0;
  BuiltinPumpModel m(s, PumpType::A4VSO);
  m.step(100.0, 0.2);
  for (int i = 0; i < 2000; ++i) m.step(0.0, 0.001);
  // 187.5 = 0.02 p + 50 (p - 380)  ->  p = 383.6 bar.
  EXPECT_NEAR(m.p_b_bar(), (187.5 + 50 * 380) / 50.02, 0.1);
}

TEST(BuiltinPumpModel, SpringCentringWithoutRotationOrPilotPressure) {
  BuiltinPlantSettings s;
  BuiltinPumpModel m(s, PumpType::A4VSO);
  m.step(100.0, 0.2);
  m.speed_rpm() = 0;
  m.step(0.0, 0.2);
  EXPECT_NEAR(m.alpha_pct(), 100.0 * std::exp(-1.0), 1.0);
  BuiltinPlantSettings internal = s;
  internal.pilot_supply = PilotSupply::Internal;
  BuiltinPumpModel q(internal, PumpType::A4VSO);
  q.step(100.0, 0.05);
  EXPECT_LT(q.alpha_pct(), 1.0);  // no pressure yet: no actuation
}

TEST(BuiltinPumpModel, OverCentrePumpDeliversAtPortA) {
  BuiltinPlantSettings s;
  BuiltinPumpModel m(s, PumpType::A4VSG);
  m.step(-100.0, 0.2);
  for (int i = 0; i < 2000; ++i) m.step(0.0, 0.001);
  EXPECT_DOUBLE_EQ(m.alpha_pct(), -100.0);
  EXPECT_NEAR(m.p_a_bar(), 327.4, 0.5);
  EXPECT_DOUBLE_EQ(m.p_b_bar(), 20.0);
}
