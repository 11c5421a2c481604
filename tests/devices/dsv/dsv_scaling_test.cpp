// The DSV's documented scaling of its set-points, actual value and valve parameters, and its own
// EMCY codes (devices::Device::value_scaling / emcy_codes).
#include <gtest/gtest.h>

#include "tests/devices/dsv/dsv_fixture.h"

namespace dsvtest {
namespace {

class DsvScaling : public DsvTest {};

TEST_F(DsvScaling, SetPointsInPercentOf16384AndCurrentsOfTheOutputStage) {
  const auto preset = dev->value_scaling(0x6300, 1);
  ASSERT_TRUE(preset);
  EXPECT_EQ(preset.unit, "%");
  EXPECT_EQ(canopen::scaled_text(8192, preset), "50.000 %");
  EXPECT_EQ(canopen::scaled_text(-16384, preset), "-100.000 %");
  EXPECT_EQ(dev->value_scaling(0x6381, 1).unit, "%");              // the actual value of mode 4
  EXPECT_DOUBLE_EQ(dev->value_scaling(0x6480, 1).apply(100000), 100.0);
  // 16384 = 1536 mA at 24 V supply.
  EXPECT_DOUBLE_EQ(dev->value_scaling(0x6343, 1).apply(16384), 1536.0);
  EXPECT_EQ(dev->value_scaling(0x6332, 1).unit, "ms");
  EXPECT_FALSE(dev->value_scaling(0x6040, 0));
  EXPECT_FALSE(dev->value_scaling(0x6300, 0));  // the number of entries
}

TEST_F(DsvScaling, CurrentsAt12VoltSupplyUseItsFullScale) {
  make(bus_mode({{"supply_voltage_nominal", "12"}}));
  EXPECT_DOUBLE_EQ(dev->value_scaling(0x6343, 1).apply(16384), 2560.0);
}

TEST_F(DsvScaling, OwnEmcyCodesFromTheManual) {
  bool solenoid_a = false;
  for (const auto& c : dev->emcy_codes())
    solenoid_a |= c.code == 0x5411 && c.text == "valve: solenoid A cable break or short circuit";
  EXPECT_TRUE(solenoid_a);
}

}  // namespace
}  // namespace dsvtest
