// WDGA position arithmetic over the bus: code sequence, scaling with a non-power-of-two range,
// wrap-around, preset (6003h/6009h) and its persistence, EnDra over a power cycle, filter, speed
// scaling and the frequency limit (digest checklist 23-30; vectors W11-W14, W22-W24, §5.4).
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

constexpr double kRpm = 2 * std::numbers::pi / 60.0;  // rad/s per rpm

class Position : public WdgaTest {
 protected:
  std::uint32_t position() {
    h().run_ms(2);
    return static_cast<std::uint32_t>(u(0x6004));
  }
};

TEST_F(Position, CountsUpClockwiseByDefaultAndDownWithBit0) {
  turn_to(1.0);
  const auto at1 = position();
  EXPECT_EQ(at1, 16384u);
  turn_to(1.5);
  EXPECT_EQ(position(), 16384u + 8192u);
  EXPECT_EQ(sdo({0x2B, 0x00, 0x60, 0x00, 0x05}), resp({0x60, 0x00, 0x60, 0x00}));
  EXPECT_EQ(u(0x6500), 5u);
  const auto p = position();
  turn_to(1.6);  // clockwise: the count falls
  EXPECT_LT(position(), p);
  turn_to(1.4);
  EXPECT_GT(position(), p);
  EXPECT_EQ(h().write(0x6000, 0, 0x0002, 2), 0x06090030u);
}

TEST_F(Position, SpeedSignFollowsTheCountingDirection) {
  device().set_input("speed", 60 * kRpm);  // one turn per second
  h().run_ms(1100);
  EXPECT_NEAR(static_cast<double>(i16(0x6030, 1)), 16384.0, 20.0);
  ASSERT_EQ(h().write(0x6000, 0, 0x0005, 2), 0u);
  h().run_ms(1100);
  EXPECT_NEAR(static_cast<double>(i16(0x6030, 1)), -16384.0, 20.0);
}

TEST_F(Position, ScalingNonPowerOfTwoRangeWrapsBothWays) {
  turn_to(0.3);
  h().run_ms(2);
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  ASSERT_EQ(h().write(0x6002, 0, 10000, 4), 0u);
  const std::uint64_t s_at_preset = static_cast<std::uint64_t>(std::floor(std::floor(0.3 * 16384) * 4096 / 16384));
  EXPECT_EQ(sdo({0x23, 0x03, 0x60, 0x00, 0x06, 0x27, 0x00, 0x00}), resp({0x60, 0x03, 0x60, 0x00}));
  EXPECT_EQ(position(), 9990u);
  turn_to(0.3 + 20.0 / 4096);
  EXPECT_EQ(position(), 10u);
  turn_to(0.3 - 10.0 / 4096);
  EXPECT_EQ(position(), 9980u);
  EXPECT_EQ(static_cast<std::int32_t>(u(0x6509)), static_cast<std::int32_t>(9990 - s_at_preset % 10000));
  EXPECT_EQ(h().write(0x6003, 0, 10000, 4), 0x06090030u);
  // Changing the scaling drops the offset [R, A-24].
  ASSERT_EQ(h().write(0x6002, 0, 20000, 4), 0u);
  EXPECT_EQ(u(0x6509), 0u);
  EXPECT_EQ(u(0x6003), 0u);
}

TEST_F(Position, ManualExampleResolution29Bits) {
  EXPECT_EQ(sdo({0x2B, 0x00, 0x60, 0x00, 0x05}), resp({0x60, 0x00, 0x60, 0x00}));
  EXPECT_EQ(sdo({0x23, 0x01, 0x60, 0x00, 0x00, 0x10}), resp({0x60, 0x01, 0x60, 0x00}));
  EXPECT_EQ(sdo({0x23, 0x02, 0x60, 0x00, 0x00, 0x00, 0x00, 0x20}), resp({0x60, 0x02, 0x60, 0x00}));
  EXPECT_EQ(sdo({0x23, 0x03, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}), resp({0x60, 0x03, 0x60, 0x00}));
  EXPECT_EQ(sdo({0x40, 0x04, 0x60, 0x00}), resp({0x43, 0x04, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}));
  turn_to(-1.0);  // one turn clockwise from 0 is one turn counter-clockwise in the count
  EXPECT_EQ(position(), 4096u);
}

TEST_F(Position, TotalRangeLimits) {
  EXPECT_EQ(h().write(0x6002, 0, 0, 4), 0x06090030u);
  EXPECT_EQ(h().write(0x6001, 0, 0, 4), 0x06090032u);
  EXPECT_EQ(h().write(0x6001, 0, 16385, 4), 0x06090031u);
  EXPECT_EQ(h().write(0x6002, 0, 0xFFFFFFFF, 4), 0u);
}

TEST_F(Position, PresetIsKeptOnlyWhenStored) {
  turn_to(2.2);
  const auto before = position();
  ASSERT_EQ(h().write(0x6003, 0, 0, 4), 0u);
  EXPECT_EQ(position(), 0u);
  h().nmt(0x81, 0x7F);
  h().run_ticks(1);
  EXPECT_EQ(position(), before);
  ASSERT_EQ(h().write(0x6003, 0, 0, 4), 0u);
  ASSERT_EQ(h().write(0x1010, 1, kSave, 4), 0u);
  h().nmt(0x81, 0x7F);
  h().run_ticks(1);
  EXPECT_EQ(position(), 0u);
  power_cycle();
  EXPECT_EQ(position(), 0u);
  EXPECT_EQ(u(0x6003), 0u);
}

TEST_F(Position, EndraCountsTurnsWhileOff) {
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  ASSERT_EQ(h().write(0x6002, 0, 100000000, 4), 0u);
  ASSERT_EQ(h().write(0x1010, 3, kSave, 4), 0u);
  turn_to(3.0);
  const auto before = position();
  device().power_off();
  for (int i = 0; i <= 100; ++i) {  // the plant turns the shaft while the node is off
    turn_to(3.0 + 1000.25 * i / 100);
    h().run_ticks(1);
  }
  boot();
  EXPECT_EQ(position(), before + static_cast<std::uint32_t>(1000.25 * 4096));
  EXPECT_EQ(u(0x6503), 0u);
  EXPECT_EQ(u(0x1001), 0u);
}

TEST_F(Position, SpeedInputTurnsTheShaftAlsoWhileOff) {
  turn_to(0.0);
  h().run_ms(2);
  device().set_input("speed", 2 * std::numbers::pi);  // 1 rev/s
  h().run_ms(1000);
  device().power_off();
  h().run_ms(3000);
  boot();
  EXPECT_NEAR(static_cast<double>(position()), 4.0 * 16384, 3 * 16384 / 1000.0 * 3);
}

TEST_F(Position, HighPrecisionPresetBySegmentedTransfer) {
  EXPECT_EQ(sdo({0x21, 0x09, 0x60, 0x00, 0x08}), resp({0x60, 0x09, 0x60, 0x00}));
  EXPECT_EQ(sdo({0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00}), resp({0x20}));
  EXPECT_EQ(sdo({0x1D, 0x00}), resp({0x30}));
  EXPECT_EQ(position(), 0x1000u);
  const auto high = h().upload(0x6008, 0);
  ASSERT_TRUE(high);
  EXPECT_EQ(*high, (std::vector<std::uint8_t>{0x00, 0x10, 0, 0, 0, 0, 0, 0}));
  // Expedited (zero-extended) works too; beyond the range it aborts.
  EXPECT_EQ(h().write(0x6009, 0, 0x2000, 4), 0u);
  EXPECT_EQ(position(), 0x2000u);
  EXPECT_EQ(h().download(0x6009, 0, {0, 0, 0, 0x40, 0, 0, 0, 0}), 0x06090030u);
}

TEST_F(Position, SpeedScalingAndSaturation) {
  EXPECT_EQ(sdo({0x2B, 0x06, 0x21, 0x01, 0x06}), resp({0x60, 0x06, 0x21, 0x01}));
  EXPECT_EQ(sdo({0x2B, 0x06, 0x21, 0x02, 0x7D}), resp({0x60, 0x06, 0x21, 0x02}));
  device().set_input("speed", 2500 * kRpm);
  h().run_ms(1100);
  EXPECT_GE(i16(0x6030, 1), 32700);
  device().set_input("speed", 5000 * kRpm);
  h().run_ms(1100);
  EXPECT_EQ(i16(0x6030, 1), 32767);
  device().set_input("speed", -5000 * kRpm);
  h().run_ms(1100);
  EXPECT_EQ(i16(0x6030, 1), -32767);
  EXPECT_EQ(h().write(0x2106, 2, 0, 2), 0x06090032u);
}

TEST_F(Position, FrequencyLimitWarningWithoutEmcy) {
  EXPECT_EQ(sdo({0x2B, 0x07, 0x21, 0x00, 0x2A}), resp({0x60, 0x07, 0x21, 0x00}));
  device().set_input("speed", 2600 * kRpm);
  h().run_ms(1100);
  EXPECT_EQ(sdo({0x40, 0x05, 0x65, 0x00}), resp({0x4B, 0x05, 0x65, 0x00, 0x01}));
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(u(0x2504, 0), 1u);
  EXPECT_EQ(u(0x2504, 1), 1u);
  device().set_input("speed", 2400 * kRpm);
  h().run_ms(1100);
  EXPECT_EQ(u(0x6505), 0u);
  EXPECT_EQ(h().write(0x2107, 0, 0, 2), 0x06090032u);
}

TEST_F(Position, FilterConstantRangeAndSmoothing) {
  EXPECT_EQ(h().write(0x2105, 1, 0, 1), 0x06090032u);
  EXPECT_EQ(sdo({0x2F, 0x05, 0x21, 0x01, 0x05}), resp({0x80, 0x05, 0x21, 0x01, 0x31, 0x00, 0x09, 0x06}));
  EXPECT_EQ(h().write(0x2105, 1, 4, 1), 0u);
  turn_to(1.0);
  h().run_ticks(1);
  const auto first = u(0x6004);
  EXPECT_GT(first, 0u);
  EXPECT_LT(first, 16384u);  // lagging behind the step
  h().run_ms(200);
  EXPECT_EQ(u(0x6004), 16384u);  // and settling exactly
  EXPECT_EQ(h().write(0x2105, 2, 0, 4), 0x06090032u);
  EXPECT_EQ(h().write(0x2105, 2, 65536, 4), 0x06090031u);
}

class PhysicalSpeed : public WdgaTest {
 protected:
  PhysicalSpeed() : WdgaTest({{"speed_units", "physical"}}) {}
};

TEST_F(PhysicalSpeed, SpeedStaysInPhysicalStepsWhateverTheScaling) {
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  device().set_input("speed", 2 * std::numbers::pi);
  h().run_ms(1100);
  EXPECT_NEAR(static_cast<double>(i16(0x6030, 1)), 16384.0, 20.0);
}

class Variant32 : public WdgaTest {
 protected:
  Variant32() : WdgaTest({{"is_32bit_variant", "on"}}) {}
};

TEST_F(Variant32, ZeroRangeMeans2To32) {
  EXPECT_EQ(u(0x6002), 0u);
  turn_to(-1.0);
  h().run_ms(2);
  EXPECT_EQ(u(0x6004), 0x100000000ull - 16384);
}

class SingleturnPosition : public WdgaTest {
 protected:
  SingleturnPosition() : WdgaTest({}, "singleturn") {}
};

TEST_F(SingleturnPosition, RestartsEveryTurnAndLimitsTheRange) {
  turn_to(7.25);
  h().run_ms(2);
  EXPECT_EQ(u(0x6004), 4096u);
  turn_to(-0.25);
  h().run_ms(2);
  EXPECT_EQ(u(0x6004), 12288u);
  EXPECT_EQ(h().write(0x6002, 0, 16385, 4), 0x06090031u);
  ASSERT_EQ(h().write(0x6001, 0, 1000, 4), 0u);
  EXPECT_EQ(h().write(0x6002, 0, 1001, 4), 0x06090031u);
  ASSERT_EQ(h().write(0x6002, 0, 360, 4), 0u);
  turn_to(0.5);  // S = 500 of 1000 per turn; 500 mod 360 = 140
  h().run_ms(2);
  EXPECT_EQ(u(0x6004), 140u);
}

}  // namespace
}  // namespace wdga::test
