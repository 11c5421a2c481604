// The HLT 1100's documented scaling of its position and speed values (6005h measuring steps).
#include <gtest/gtest.h>

#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

class HltScaling : public Hlt1100Test {};

TEST_F(HltScaling, PositionInStepsOfTheMeasuringStepAndSpeedInTheSpeedStep) {
  auto& d = device();
  const auto position = d.value_scaling(0x6020, 1);
  ASSERT_TRUE(position);
  EXPECT_EQ(position.unit, "mm");
  EXPECT_EQ(canopen::scaled_text(1234, position), "123.4 mm");  // 6005h:01 = 100000 nm = 0.1 mm
  const auto speed = d.value_scaling(0x6030, 1);
  EXPECT_EQ(speed.unit, "mm/s");
  EXPECT_EQ(canopen::scaled_text(500, speed), "50.0 mm/s");  // 6005h:02 = 10 × 0.01 mm/s
  EXPECT_EQ(d.value_scaling(0x6010, 1).unit, "mm");
  EXPECT_FALSE(d.value_scaling(0x6020, 0));
  bool no_magnet = false;
  for (const auto& c : d.emcy_codes()) no_magnet |= c.code == 0xFF00;
  EXPECT_TRUE(no_magnet);
}

}  // namespace
}  // namespace hlt1100::test
