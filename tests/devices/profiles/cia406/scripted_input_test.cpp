#include "devices/profiles/cia406/scripted_input.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cia406 {
namespace {

TEST(ScriptedInput, HoldRampSine) {
  ScriptedInput s;
  EXPECT_EQ(s.parse("hold"), "");
  EXPECT_EQ(s.value(0.3, 10), 0.3);
  EXPECT_EQ(s.parse("ramp:0.1"), "");
  EXPECT_DOUBLE_EQ(s.value(0.3, 2), 0.5);
  EXPECT_DOUBLE_EQ(s.derivative(2), 0.1);
  EXPECT_EQ(s.parse("sine:2,0.5"), "");
  EXPECT_NEAR(s.value(1.0, 0.5), 3.0, 1e-12);
  EXPECT_NEAR(s.derivative(0), 2 * 2 * std::numbers::pi * 0.5, 1e-12);
}

TEST(ScriptedInput, RejectsMalformedText) {
  ScriptedInput s;
  EXPECT_NE(s.parse("ramp:"), "");
  EXPECT_NE(s.parse("ramp:x"), "");
  EXPECT_NE(s.parse("sine:1"), "");
  EXPECT_NE(s.parse("sine:1,-2"), "");
  EXPECT_NE(s.parse("square:1"), "");
  EXPECT_NE(s.parse("ramp:inf"), "");
}

}  // namespace
}  // namespace cia406
