// CiA 406 CAM unit: switching with hysteresis, polarity/enable, the low-limit write rule.
#include "devices/profiles/cia406/cam_unit.h"

#include <gtest/gtest.h>

namespace cia406 {
namespace {

TEST(Cam, InclusiveLimitsAndHysteresisInTheDirectionOfTravel) {
  Cam c{.low = 0, .high = 2048, .hysteresis = 10};
  EXPECT_TRUE(c.update(0));
  EXPECT_TRUE(c.update(2058));
  EXPECT_FALSE(c.update(2059));
  EXPECT_FALSE(c.update(2049));
  EXPECT_TRUE(c.update(2048));
  EXPECT_TRUE(c.update(-10));
  EXPECT_FALSE(c.update(-11));
  EXPECT_FALSE(c.update(-5));
}

TEST(CamUnit, StateBitsFromEnablePolarityAndTheLowLimitRule) {
  canopen::ObjectDictionary od;
  CamUnit::add_objects(od);
  CamUnit unit;
  unit.bind(od);
  od.set<std::int32_t>(CamUnit::kHighLimit, 1, 100);
  od.set<std::uint8_t>(CamUnit::kEnable, 1, 0x03);
  EXPECT_EQ(unit.update(50), 0x01);  // CAM2 [0, 0]
  EXPECT_EQ(unit.update(0), 0x03);
  od.set<std::uint8_t>(CamUnit::kPolarity, 1, 0x02);
  EXPECT_EQ(unit.update(50), 0x03);
  EXPECT_EQ(od.get<int>(CamUnit::kState, 1), 0x03);
  // Low limit: a changed value must stay below the high limit; the same value is accepted.
  const std::uint8_t bad[] = {0x64, 0, 0, 0}, same[] = {0, 0, 0, 0}, good[] = {0x63, 0, 0, 0};
  EXPECT_EQ(od.write(CamUnit::kLowLimit, 1, bad, canopen::Origin::Sdo), canopen::SdoAbort::MaxLessThanMin);
  EXPECT_EQ(od.write(CamUnit::kLowLimit + 1, 1, same, canopen::Origin::Sdo), canopen::SdoAbort::None);
  EXPECT_EQ(od.write(CamUnit::kLowLimit, 1, good, canopen::Origin::Sdo), canopen::SdoAbort::None);
}

}  // namespace
}  // namespace cia406
