// HLT 1100 store/restore (1010h/1011h) with its 3 s of bus silence, Reset Node semantics, preset
// persistence and the EEPROM fault (digest checklist 20-22; test vectors 21-24).
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

class Store : public Hlt1100Test {
 protected:
  /// Sends "save" and waits for the answer that comes after the silent time.
  void save() {
    h().take();
    h().send(0x605, {0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65});
    h().run_ms(3001);
    ASSERT_EQ(h().take(), Frames{Frame(0x585, eight({0x60, 0x10, 0x10, 0x01}))});
  }
};

TEST_F(Store, SaveSilencesTheNodeForThreeSecondsThenAnswers) {
  start();
  ASSERT_EQ(h().write(0x6200, 0, 50, 2), 0u);
  h().take();
  h().send(0x605, {0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65});
  for (int i = 0; i < 29; ++i) {
    h().send(Frame::remote(0x705, 1));
    h().send(Frame(0x080, std::vector<std::uint8_t>{}));
    h().run_ms(100);
    ASSERT_TRUE(h().take().empty()) << "at " << i * 100 << " ms";
  }
  h().run_ms(101);
  const auto after = h().take();
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.front(), Frame(0x585, eight({0x60, 0x10, 0x10, 0x01})));
  // Saved values survive a power cycle.
  power_cycle();
  EXPECT_EQ(h().read_u(0x6200, 0), 50u);
  EXPECT_EQ(h().read_u(0x1800, 5), 50u);
}

TEST_F(Store, WrongSignatureAbortsAtOnce) {
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0, 0, 0, 0}), Frame(0x585, eight({0x80, 0x10, 0x10, 0x01, 0, 0, 0, 0x08})));
  EXPECT_EQ(h().write(0x1010, 1, 0x12345678, 4), 0x08000000u);
  EXPECT_EQ(h().write(0x1011, 1, kSave, 4), 0x08000000u);
}

TEST_F(Store, ResetNodeLoadsTheStoredValues) {
  ASSERT_EQ(h().write(0x6200, 0, 20, 2), 0u);
  save();
  ASSERT_EQ(h().write(0x6200, 0, 70, 2), 0u);
  h().nmt(0x81, 5);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h().read_u(0x6200, 0), 20u);
}

TEST_F(Store, RestoreGivesFactoryValuesAfterResetNodeButKeepsNodeIdAndBitRate) {
  ASSERT_EQ(h().write(0x6200, 0, 20, 2), 0u);
  ASSERT_EQ(h().write(0x6000, 0, 8, 2), 0u);
  ASSERT_EQ(h().write(0x6010, 1, 10, 4), 0u);
  save();
  h().take();
  h().send(0x605, {0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64});
  h().run_ms(2990);
  EXPECT_TRUE(h().take().empty());  // restore is silent too
  h().run_ms(20);
  EXPECT_EQ(h().take(), Frames{Frame(0x585, eight({0x60, 0x11, 0x10, 0x01}))});
  EXPECT_EQ(h().read_u(0x6200, 0), 20u);  // still active until the reset
  h().nmt(0x81, 5);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});  // same node-ID
  EXPECT_EQ(h().read_u(0x6200, 0), 0u);
  EXPECT_EQ(h().read_u(0x6000, 0), 0u);
  EXPECT_EQ(read_i32(0x6010, 1), 0);
  EXPECT_EQ(read_i32(0x650C, 1), 0);
  EXPECT_EQ(device().node().lss()->active_bit_rate(), 3);
}

TEST_F(Store, PresetIsKeptOnlyWhenSaved) {
  ASSERT_EQ(h().write(0x6010, 1, 0, 4), 0u);
  power_cycle();
  EXPECT_EQ(read_i32(0x6020, 1), 1000);  // not saved: the old offset
  ASSERT_EQ(h().write(0x6010, 1, 0, 4), 0u);
  save();
  power_cycle();
  EXPECT_EQ(read_i32(0x6020, 1), 0);
  EXPECT_EQ(read_i32(0x650C, 1), -1000);
}

TEST_F(Store, EepromFaultAbortsSaveAndSetsAlarmBit12) {
  device().inject_fault("eeprom_error", true);
  EXPECT_EQ(h().write(0x1010, 1, kSave, 4), 0x06060000u);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x50, 0x21})});
  EXPECT_EQ(h().read_u(0x6503, 0), 0x1000u);
  EXPECT_EQ(h().write(0x1011, 1, kLoad, 4), 0x06060000u);
  device().inject_fault("eeprom_error", false);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
}

class LiteralEepromAbort : public Hlt1100Test {
 protected:
  LiteralEepromAbort() : Hlt1100Test({{"eeprom_abort", "0x06000006"}, {"reset_node_loads", "factory"}}) {}
};

TEST_F(LiteralEepromAbort, PrintedAbortCodeAndFactoryResetNode) {
  ASSERT_EQ(h().write(0x6000, 0, 8, 2), 0u);
  h().write(0x1010, 1, kSave, 4);
  h().run_ms(3001);
  h().nmt(0x81, 5);
  h().run_ticks(1);
  EXPECT_EQ(h().read_u(0x6000, 0), 0u);  // Reset Node: "profile parameters to default values"
  power_cycle();
  EXPECT_EQ(h().read_u(0x6000, 0), 8u);  // a power-on still loads the stored value
  device().inject_fault("eeprom_error", true);
  EXPECT_EQ(h().write(0x1010, 1, kSave, 4), 0x06000006u);
}

class AutoSavedPreset : public Hlt1100Test {
 protected:
  AutoSavedPreset() : Hlt1100Test({{"preset_auto_save", "on"}}) {}
};

TEST_F(AutoSavedPreset, PresetSurvivesAPowerCycleWithoutSave) {
  ASSERT_EQ(h().write(0x6010, 1, 0, 4), 0u);
  power_cycle();
  EXPECT_EQ(read_i32(0x6020, 1), 0);
}

TEST_F(Store, EepromFaultAtPowerOnIsReportedAfterBootUp) {
  device().inject_fault("eeprom_error", true);
  power_cycle();
  h().run_ticks(1);
  EXPECT_EQ(h().take(), (Frames{Frame(0x705, {0x00}), emcy({0x00, 0x50, 0x21})}));
}

}  // namespace
}  // namespace hlt1100::test
