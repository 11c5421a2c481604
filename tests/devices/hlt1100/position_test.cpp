// HLT 1100 measurement: preset, counting direction, speed, parameter range handling (digest
// checklist 23-25; test vectors 26, 27).
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

class Position : public Hlt1100Test {
 protected:
  void settle() { h().run_ms(2); }
};

TEST_F(Position, RawPositionIsTenthsOfMillimetres) {
  magnet_mm(123.4);
  settle();
  EXPECT_EQ(read_i32(0x6020, 1), 1234);
  magnet_mm(0.04);
  settle();
  EXPECT_EQ(read_i32(0x6020, 1), 0);
  magnet_mm(499.96);  // rounds to 5000, the last valid step is 4999
  settle();
  EXPECT_EQ(read_i32(0x6020, 1), 4999);
}

TEST_F(Position, PresetMakesTheOutputTheWrittenValue) {
  magnet_mm(123.4);
  settle();
  EXPECT_EQ(sdo({0x23, 0x10, 0x60, 0x01, 0, 0, 0, 0}), Frame(0x585, eight({0x60, 0x10, 0x60, 0x01})));
  EXPECT_EQ(sdo({0x40, 0x20, 0x60, 0x01}), Frame(0x585, eight({0x43, 0x20, 0x60, 0x01, 0, 0, 0, 0})));
  EXPECT_EQ(sdo({0x40, 0x0C, 0x65, 0x01}), Frame(0x585, eight({0x43, 0x0C, 0x65, 0x01, 0x2E, 0xFB, 0xFF, 0xFF})));
  EXPECT_EQ(read_i32(0x6010, 1), 0);
  magnet_mm(133.4);
  settle();
  EXPECT_EQ(read_i32(0x6020, 1), 100);
  // The TPDO carries the same value.
  EXPECT_EQ(start(), Frames{Frame(0x185, {100, 0, 0, 0})});
}

TEST_F(Position, DirectionCountsDownTowardTheRodEnd) {
  magnet_mm(100.0);
  settle();
  ASSERT_EQ(sdo({0x2B, 0x00, 0x60, 0x00, 0x08, 0x00}), Frame(0x585, eight({0x60, 0x00, 0x60, 0x00})));
  EXPECT_EQ(sdo({0x40, 0x00, 0x65, 0x00}), Frame(0x585, eight({0x4B, 0x00, 0x65, 0x00, 0x08, 0x00})));
  settle();
  const auto at100 = read_i32(0x6020, 1);
  EXPECT_EQ(at100, 4999 - 1000);
  magnet_mm(110.0);
  settle();
  EXPECT_EQ(read_i32(0x6020, 1), at100 - 100);
  ASSERT_EQ(h().write(0x6000, 0, 0, 2), 0u);
  settle();
  EXPECT_EQ(read_i32(0x6020, 1), 1100);
  EXPECT_EQ(h().read_u(0x6500, 0), 0u);
}

TEST_F(Position, OutOfRangeParametersRaiseTheParameterAlarm) {
  // Preset range 0..N-1 (N = 5000): accepted by SDO, not applied, 6503h bit 13 and EMCY 0x6300.
  EXPECT_EQ(h().write(0x6010, 1, 5000, 4), 0u);
  h().run_ticks(1);  // the EMCY follows the SDO answer
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x63, 0x21})});
  EXPECT_EQ(read_i32(0x6010, 1), 0);
  EXPECT_EQ(read_i32(0x650C, 1), 0);
  EXPECT_EQ(h().read_u(0x6503, 0), 0x2000u);
  EXPECT_EQ(h().write(0x6000, 0, 0x0001, 2), 0u);  // reserved bit: same handling
  EXPECT_EQ(h().read_u(0x6000, 0), 0u);
  // A valid value clears the alarm (EMCY "error reset").
  h().take();
  EXPECT_EQ(h().write(0x6010, 1, 4999, 4), 0u);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(read_i32(0x6020, 1), 4999);
  EXPECT_EQ(h().read_u(0x6503, 0), 0u);
  EXPECT_EQ(h().write(0x6010, 1, static_cast<std::uint32_t>(-1), 4), 0u);
  EXPECT_EQ(read_i32(0x6010, 1), 4999);
}

TEST_F(Position, PresetWhileTheMagnetIsMissingAborts) {
  device().inject_fault("magnet_lost", true);
  settle();
  EXPECT_EQ(h().write(0x6010, 1, 0, 4), 0x08000000u);
}

class StrictParameters : public Hlt1100Test {
 protected:
  StrictParameters() : Hlt1100Test({{"parameter_error", "abort"}}) {}
};

TEST_F(StrictParameters, OutOfRangeWritesAbort06090030) {
  EXPECT_EQ(h().write(0x6010, 1, 5000, 4), 0x06090030u);
  EXPECT_EQ(h().write(0x6000, 0, 0x0004, 2), 0x06090030u);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(h().read_u(0x6503, 0), 0u);
}

TEST_F(Position, SpeedIsPositiveWhenThePositionRisesAndDoesNotSpikeOnPreset) {
  // +50 mm/s for 200 ms: 6030h ≈ +500 (0.1 mm/s units with 6005h:02 = 10).
  for (int ms = 0; ms < 200; ++ms) {
    magnet_mm(100.0 + 0.05 * ms);
    h().run_ticks(1);
  }
  EXPECT_NEAR(static_cast<double>(read_i16(0x6030, 1)), 500.0, 10.0);
  ASSERT_EQ(h().write(0x6010, 1, 0, 4), 0u);  // the output jumps, the speed does not
  for (int ms = 200; ms < 205; ++ms) {
    magnet_mm(100.0 + 0.05 * ms);
    h().run_ticks(1);
    EXPECT_NEAR(static_cast<double>(read_i16(0x6030, 1)), 500.0, 10.0);
  }
  ASSERT_EQ(h().write(0x6000, 0, 0x0008, 2), 0u);  // counting down: the speed turns negative
  magnet_mm(100.0 + 0.05 * 205);
  h().run_ticks(1);
  EXPECT_NEAR(static_cast<double>(read_i16(0x6030, 1)), -500.0, 10.0);
  // Standing still: 0.
  h().run_ms(50);
  EXPECT_EQ(read_i16(0x6030, 1), 0);
}

TEST_F(Position, SpeedSaturatesInsteadOfWrapping) {
  for (int ms = 0; ms < 50; ++ms) {
    magnet_mm(10.0 + 5.0 * ms);  // 5 m/s = 50000 units
    h().run_ticks(1);
  }
  EXPECT_EQ(read_i16(0x6030, 1), 32767);
}

class ScriptedRamp : public Hlt1100Test {
 protected:
  ScriptedRamp() : Hlt1100Test({{"signal", "ramp:0.1"}}) {}
};

TEST_F(ScriptedRamp, StandaloneSignalMovesTheMagnet) {
  const auto t0 = read_i32(0x6020, 1);
  h().run_ms(100);  // 0.1 m/s for 0.1 s = 10 mm = 100 steps
  EXPECT_NEAR(static_cast<double>(read_i32(0x6020, 1) - t0), 100.0, 2.0);
  EXPECT_NEAR(static_cast<double>(read_i16(0x6030, 1)), 1000.0, 20.0);
}

}  // namespace
}  // namespace hlt1100::test
