// Four-quadrant command value ramp and rate limiter: timing within one control cycle.
#include "devices/profiles/dsp408/command_value_ramp.h"

#include <gtest/gtest.h>

using dsp408::CommandValueRamp;

namespace {
/// Runs 1 ms steps until the output reaches `target`; returns the number of steps.
int steps_to(CommandValueRamp& r, double target, int limit = 100000) {
  int n = 0;
  while (r.output() != target && n < limit) {
    r.step(target, 0.001);
    ++n;
  }
  return n;
}
}  // namespace

TEST(CommandValueRamp, FullScaleRiseTakesTheRampTime) {
  CommandValueRamp r;
  r.set_times({.a_up = 1.0, .a_down = 2.0, .b_up = 0.5, .b_down = 0.25});
  EXPECT_EQ(steps_to(r, 16384), 1000);
  EXPECT_EQ(steps_to(r, 0), 2000);
  EXPECT_EQ(steps_to(r, -16384), 500);
  EXPECT_EQ(steps_to(r, 0), 250);
}

TEST(CommandValueRamp, PartialChangeTakesItsShareAndIsLinear) {
  CommandValueRamp r;
  r.set_times({.a_up = 1.0});
  r.step(8192, 0.250);
  EXPECT_DOUBLE_EQ(r.output(), 4096);
  EXPECT_TRUE(r.running(8192));
  EXPECT_EQ(steps_to(r, 8192), 250);
  EXPECT_FALSE(r.running(8192));
}

TEST(CommandValueRamp, ZeroCrossingCostsDownPlusUpInsideOneStep) {
  CommandValueRamp r;
  r.set_times({.a_up = 1.0, .a_down = 1.0, .b_up = 1.0, .b_down = 1.0});
  r.reset(1638.4);  // +10 %
  r.step(-1638.4, 0.150);  // 100 ms down to 0, then 50 ms on the B side
  EXPECT_NEAR(r.output(), -819.2, 1e-9);
}

TEST(CommandValueRamp, ZeroTimeIsAStepAndDisabledFollowsAtOnce) {
  CommandValueRamp r;
  r.step(5000, 0.001);
  EXPECT_EQ(r.output(), 5000);
  r.set_times({.a_up = 10});
  r.set_enabled(false);
  r.step(16384, 0.001);
  EXPECT_EQ(r.output(), 16384);
}

TEST(RateLimiter, RiseAndFallRates) {
  dsp408::RateLimiter l;
  l.set_rates(1000, 500);
  l.step(100, 0.05);
  EXPECT_DOUBLE_EQ(l.output(), 50);
  l.step(100, 0.1);
  EXPECT_DOUBLE_EQ(l.output(), 100);
  l.step(0, 0.1);
  EXPECT_DOUBLE_EQ(l.output(), 50);
  l.set_rates(0, 0);
  l.step(-7, 0.001);
  EXPECT_DOUBLE_EQ(l.output(), -7);
}

TEST(CommandValueRamp, RunningOnlyWhileTheRampTakesTime) {
  CommandValueRamp r;
  r.set_times({.a_up = 1.0, .a_down = 0});
  EXPECT_TRUE(r.running(100));
  EXPECT_NEAR(r.time_to(8192), 0.5, 1e-12);
  r.reset(100);
  EXPECT_FALSE(r.running(0));  // A down is a step
  EXPECT_FALSE(r.running(100));
  r.set_enabled(false);
  EXPECT_FALSE(r.running(200));
}
