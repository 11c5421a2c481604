// CiA 406 linear arithmetic (HLT digest §4.2/§4.3).
#include "devices/profiles/cia406/linear_position.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cia406 {
namespace {

TEST(LinearPosition, StepsRoundAndClampToTheRange) {
  LinearConfig c;  // 0.1 mm, 5000 steps
  EXPECT_EQ(steps_from_metres(0.12345, c), 1235);
  EXPECT_EQ(steps_from_metres(-0.01, c), 0);
  EXPECT_EQ(steps_from_metres(0.6, c), 4999);
  EXPECT_EQ(steps_from_metres(std::nan(""), c), 0);
}

TEST(LinearPosition, DirectionKeepsTheRangeAndPresetMakesTheOutput) {
  LinearConfig c;
  c.manufacturer_offset = 7;
  EXPECT_EQ(directed_raw(1000, c), 1000);
  c.decreasing = true;
  EXPECT_EQ(directed_raw(1000, c), 3999);
  EXPECT_EQ(directed_raw(0, c), 4999);
  const auto offset = linear_offset_for_preset(0, 3999, c);
  EXPECT_EQ(offset, -4006);
  EXPECT_EQ(linear_position(3999, offset, c), 0);
  EXPECT_EQ(linear_position(3899, offset, c), -100);
}

}  // namespace
}  // namespace cia406
