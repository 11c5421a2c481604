// Current stage: Imin/Imax scaling, dead-band jump, inverted curve, characteristic curve.
#include "devices/profiles/dsp408/solenoid_current.h"

#include <gtest/gtest.h>

#include "devices/profiles/dsp408/characteristic_curve.h"

using dsp408::CharacteristicCurve;
using dsp408::solenoid_current;
using dsp408::SolenoidCurve;

TEST(SolenoidCurrent, IminPlusSpanTimesDemand) {
  const SolenoidCurve s{.i_min = 0.2, .i_max = 1.0};
  EXPECT_DOUBLE_EQ(solenoid_current(s, 0), 0);
  EXPECT_DOUBLE_EQ(solenoid_current(s, 0.5), 0.6);
  EXPECT_DOUBLE_EQ(solenoid_current(s, 1), 1.0);
  EXPECT_DOUBLE_EQ(solenoid_current(s, 1.5), 1.0);  // limited to Imax
  EXPECT_DOUBLE_EQ(solenoid_current(s, -1), 0);
}

TEST(SolenoidCurrent, DeadBandJumpsFromZeroToImin) {
  // DSV type 1: threshold 10 %, the rest stretched to Imin..Imax.
  const SolenoidCurve s{.i_min = 0.25, .i_max = 0.75, .threshold = 0.1, .rescale = true};
  EXPECT_DOUBLE_EQ(solenoid_current(s, 0.1), 0);
  EXPECT_NEAR(solenoid_current(s, 0.1000001), 0.25, 1e-6);  // the jump
  EXPECT_DOUBLE_EQ(solenoid_current(s, 0.55), 0.5);
  EXPECT_DOUBLE_EQ(solenoid_current(s, 1), 0.75);
  // MD2: below the dead band 0, above it Imin + span·a (no stretching).
  const SolenoidCurve m{.i_min = 0.2, .i_max = 1.0, .threshold = 0.01};
  EXPECT_DOUBLE_EQ(solenoid_current(m, 0.005), 0);
  EXPECT_DOUBLE_EQ(solenoid_current(m, 0.5), 0.6);
}

TEST(SolenoidCurrent, FallingCurveAndIminAtZero) {
  const SolenoidCurve s{.i_min = 0.2, .i_max = 1.0, .falling = true, .imin_at_zero = true};
  EXPECT_DOUBLE_EQ(solenoid_current(s, 0), 1.0);
  EXPECT_DOUBLE_EQ(solenoid_current(s, 1), 0.2);
  const SolenoidCurve r{.i_min = 0.2, .i_max = 1.0, .imin_at_zero = true};
  EXPECT_DOUBLE_EQ(solenoid_current(r, 0), 0.2);
}

TEST(CharacteristicCurve, IdentityByDefaultAndPiecewiseLinear) {
  CharacteristicCurve c;
  EXPECT_DOUBLE_EQ(c.map(0.37), 0.37);
  c.set_point(5, {0.5, 0.2});  // pull the middle point down
  EXPECT_DOUBLE_EQ(c.map(0.5), 0.2);
  EXPECT_DOUBLE_EQ(c.map(0.45), 0.3);  // between (0.4, 0.4) and (0.5, 0.2)
  const SolenoidCurve s{.i_min = 0, .i_max = 1.0};
  EXPECT_DOUBLE_EQ(solenoid_current(s, 0.5, &c), 0.2);
}
