// Closed-loop controller: proportional part per sign, integrator windows, limits.
#include "devices/profiles/dsp408/pid_controller.h"

#include <gtest/gtest.h>

using dsp408::PidController;
using dsp408::PidParameters;

TEST(PidController, ProportionalGainPerSign) {
  PidController c;
  c.set_parameters({.kp_pos = 2, .kp_neg = 0.5});
  EXPECT_DOUBLE_EQ(c.update(0.1, 0, 0.001), 0.2);
  EXPECT_DOUBLE_EQ(c.update(-0.1, 0, 0.001), -0.05);
  EXPECT_DOUBLE_EQ(c.update(2, 0, 0.001), 1);  // limited
}

TEST(PidController, IntegratorAndItsWindows) {
  PidController c;
  c.set_parameters({.ki_pos = 10, .ki_neg = 10, .i_window_outside_pos = 0.5, .i_window_inside_pos = 0.01});
  for (int i = 0; i < 100; ++i) c.update(0.1, 0, 0.001);
  EXPECT_NEAR(c.integral(), 0.1, 1e-9);
  c.update(0.005, 0, 0.001);  // inside: held
  EXPECT_NEAR(c.integral(), 0.1, 1e-9);
  c.update(0.6, 0, 0.001);  // outside: reset
  EXPECT_EQ(c.integral(), 0);
  PidParameters p = c.parameters();
  p.hold_i_outside = true;
  c.set_parameters(p);
  for (int i = 0; i < 100; ++i) c.update(0.1, 0, 0.001);
  c.update(0.6, 0, 0.001);
  EXPECT_NEAR(c.integral(), 0.1, 1e-9);
}

TEST(PidController, FeedForwardAndOneSidedOutput) {
  PidController c;
  c.set_parameters({.ff_w = 1, .out_min = 0, .out_max = 1});
  EXPECT_DOUBLE_EQ(c.update(0, 0.3, 0.001), 0.3);
  EXPECT_DOUBLE_EQ(c.update(0, -0.3, 0.001), 0);
}
