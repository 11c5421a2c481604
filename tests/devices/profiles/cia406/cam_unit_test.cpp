// CiA 406 CAM unit: switching with hysteresis, polarity/enable, the low-limit write rule.
#include "devices/profiles/cia406/cam_unit.h"

#include <gtest/gtest.h>

#include <array>
#include <random>

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

TEST(CamUnit, EveryCycleIsTheCamRuleOnTheLimitsOfThatCycle) {
  // Limits, hysteresis, enable and polarity rewritten at random between cycles (as SDO, PDO or a
  // reset would): the published state is the rule applied to the values of that very cycle.
  canopen::ObjectDictionary od;
  CamUnit::add_objects(od);
  CamUnit unit;
  unit.bind(od);
  std::array<Cam, CamUnit::kCams> ref{};
  std::mt19937_64 rng(6300);
  std::int64_t x = 500;
  for (int cycle = 0; cycle < 20000; ++cycle) {
    if (rng() % 4 == 0) {
      const int k = static_cast<int>(rng() % CamUnit::kCams);
      const auto lo = static_cast<std::int32_t>(rng() % 1000);
      od.set<std::int32_t>(static_cast<std::uint16_t>(CamUnit::kLowLimit + k), 1, lo);
      od.set<std::int32_t>(static_cast<std::uint16_t>(CamUnit::kHighLimit + k), 1, lo + static_cast<std::int32_t>(rng() % 300));
      od.set<std::uint32_t>(static_cast<std::uint16_t>(CamUnit::kHysteresis + k), 1,
                            rng() % 5 == 0 ? 0xFFFFFFFFu : static_cast<std::uint32_t>(rng() % 40));
    }
    if (rng() % 50 == 0) od.set<std::uint8_t>(CamUnit::kEnable, 1, static_cast<std::uint8_t>(rng()));
    if (rng() % 50 == 0) od.set<std::uint8_t>(CamUnit::kPolarity, 1, static_cast<std::uint8_t>(rng()));
    x += static_cast<std::int64_t>(rng() % 41) - 20;
    std::uint8_t want = 0;
    const auto enabled = od.get<std::uint8_t>(CamUnit::kEnable, 1), inverted = od.get<std::uint8_t>(CamUnit::kPolarity, 1);
    for (int k = 0; k < CamUnit::kCams; ++k) {
      Cam& c = ref[static_cast<std::size_t>(k)];
      c.low = od.get<std::int32_t>(static_cast<std::uint16_t>(CamUnit::kLowLimit + k), 1);
      c.high = od.get<std::int32_t>(static_cast<std::uint16_t>(CamUnit::kHighLimit + k), 1);
      c.hysteresis = od.get<std::uint32_t>(static_cast<std::uint16_t>(CamUnit::kHysteresis + k), 1);
      const bool inside = c.update(x);
      const auto bit = static_cast<std::uint8_t>(1u << k);
      if ((enabled & bit) && (inside != ((inverted & bit) != 0))) want |= bit;
    }
    ASSERT_EQ(unit.update(x), want) << "cycle " << cycle;
    ASSERT_EQ(od.get<std::uint8_t>(CamUnit::kState, 1), want);
  }
}

}  // namespace
}  // namespace cia406
