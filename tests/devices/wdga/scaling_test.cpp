// The WDGA's documented scaling of its position values and its own EMCY codes, as the API and the
// frame decoder read them (devices::Device::value_scaling / emcy_codes).
#include <gtest/gtest.h>

#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

class WdgaScaling : public WdgaTest {};

TEST_F(WdgaScaling, MultiturnPositionReadsInTurnsOfTheMeasuringUnitsPerRevolution) {
  const auto s = device().value_scaling(0x6004, 0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s.unit, "turns");
  EXPECT_DOUBLE_EQ(s.apply(16384 * 3), 3.0);  // 6001h = 16384 steps per turn
  EXPECT_EQ(canopen::scaled_text(16384 * 3 + 8192, s), "3.50000 turns");
  // 6001h = 4096: a turn is 4096 steps.
  od().set<std::uint32_t>(0x6001, 0, 4096);
  EXPECT_DOUBLE_EQ(device().value_scaling(0x6004, 0).apply(4096), 1.0);
  // Scaling off (6000h bit 2 clear): the physical 16384 steps, whatever 6001h says.
  od().set<std::uint16_t>(0x6000, 0, 0x0000);
  EXPECT_DOUBLE_EQ(device().value_scaling(0x6004, 0).apply(16384), 1.0);
  EXPECT_FALSE(device().value_scaling(0x6040, 0));  // no documented unit
}

class SingleturnScaling : public WdgaTest {
 protected:
  SingleturnScaling() : WdgaTest({}, "singleturn") {}
};

TEST_F(SingleturnScaling, PositionReadsInDegrees) {
  const auto s = device().value_scaling(0x6004, 0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s.unit, "°");
  EXPECT_DOUBLE_EQ(s.apply(4096), 90.0);
}

TEST_F(WdgaScaling, OwnEmcyCodesFromTheManual) {
  bool temperature = false;
  for (const auto& c : device().emcy_codes()) temperature |= c.code == 0x4200 && c.text == "device temperature out of tolerance";
  EXPECT_TRUE(temperature);
}

}  // namespace
}  // namespace wdga::test
