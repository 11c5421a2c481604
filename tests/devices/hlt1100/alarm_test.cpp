// HLT 1100 alarms, error register, error list and EMCY (digest checklist 26-30; test vectors
// 35-37). Interpretation: reading 0x1001 consumes one list entry [M §12.2.1], so the checks read
// 0x1003 before 0x1001.
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

class Alarms : public Hlt1100Test {
 protected:
  Alarms() {
    start();
    h().take();
  }
};

TEST_F(Alarms, MagnetRemovedSendsOneEmcyAndHoldsTheLastValue) {
  ASSERT_EQ(h().write(0x6200, 0, 10, 2), 0u);
  h().take();
  device().inject_fault("magnet_lost", true);
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0xFF, 0x21})});
  h().run_ms(25);
  // The 10 ms cycle goes on (at 10 and 20 ms after the 6200h write) with the last valid value.
  const Frame held(0x185, {0xE8, 0x03, 0x00, 0x00});
  EXPECT_EQ(h().take(), (Frames{held, held}));
  EXPECT_EQ(sdo({0x40, 0x03, 0x65, 0x00}), Frame(0x585, eight({0x4B, 0x03, 0x65, 0x00, 0x01})));
  EXPECT_EQ(h().read_u(0x1003, 0), 1u);
  EXPECT_EQ(h().read_u(0x1003, 1), 0x0000FF00u);
  EXPECT_EQ(read_i16(0x6030, 1), 0);
  EXPECT_EQ(h().read_u(0x1001, 0), 0x21u);
}

TEST_F(Alarms, MagnetBackSendsErrorResetAndTheListKeepsItsEntry) {
  device().inject_fault("magnet_lost", true);
  h().run_ms(1);
  h().take();
  device().inject_fault("magnet_lost", false);
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(h().read_u(0x6503, 0), 0u);
  EXPECT_EQ(h().read_u(0x1003, 0), 1u);
  EXPECT_EQ(h().read_u(0x1001, 0), 0u);
}

TEST_F(Alarms, ReadingTheErrorRegisterConsumesOneEntry) {
  device().inject_fault("magnet_lost", true);
  h().run_ms(1);
  device().inject_fault("magnet_lost", false);
  h().run_ms(1);
  h().take();
  ASSERT_EQ(h().read_u(0x1003, 0), 1u);
  EXPECT_EQ(sdo({0x40, 0x01, 0x10, 0x00}), Frame(0x585, eight({0x4F, 0x01, 0x10, 0x00, 0x00})));
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(h().read_u(0x1003, 0), 0u);
  EXPECT_EQ(h().read_u(0x1001, 0), 0u);
  h().run_ticks(1);
  EXPECT_TRUE(h().take().empty());  // nothing left: no EMCY
}

TEST_F(Alarms, OtherWaysToClearTheList) {
  device().inject_fault("second_magnet", true);
  h().run_ms(1);
  device().inject_fault("second_magnet", false);
  h().run_ms(1);
  h().take();
  EXPECT_EQ(h().write(0x1003, 0, 1, 1), 0x06090030u);
  EXPECT_EQ(sdo({0x2F, 0x03, 0x10, 0x00, 0x00}), Frame(0x585, eight({0x60, 0x03, 0x10, 0x00})));
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(h().read_u(0x1003, 0), 0u);
  EXPECT_EQ(h().read_u(0x1003, 1), 0u);
}

TEST_F(Alarms, CanControllerErrorLatchesTheCommunicationBit) {
  device().inject_fault("can_error", true);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x81, 0x11})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
  EXPECT_EQ(h().read_u(0x1003, 1), 0x8100u);
  EXPECT_EQ(h().read_u(0x1001, 0), 0x11u);  // consumes the entry, the bit goes with it
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  EXPECT_EQ(h().read_u(0x1001, 0), 0u);
}

TEST_F(Alarms, BusOffRecoveryIsACanControllerError) {
  // Digest §3: 8100h covers bus-off recovery (e.g. a bus-off a scenario made on the wire).
  h().take();
  device().node().communication_error(canopen::CommError::BusOffRecovered);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x81, 0x11})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(Alarms, OutOfRangeAndSecondMagnetAreAlsoPositionErrors) {
  magnet_mm(500.0);  // the range is 0 <= x < 500 mm
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0xFF, 0x21})});
  magnet_mm(499.0);
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
  device().set_input("magnet_count", 2);
  device().set_input("position2", 0.6);  // outside the range: not seen
  h().run_ms(1);
  EXPECT_TRUE(h().take().empty());
  device().set_input("position2", 0.2);
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0xFF, 0x21})});
  EXPECT_EQ(h().read_u(0x1003, 0), 2u);  // the count runs, one entry kept
  device().set_input("magnet_count", 0);
  h().run_ms(1);
  EXPECT_TRUE(h().take().empty());  // still the same condition
}

TEST_F(Alarms, MissingMagnetAtPowerOnGivesEmcyRightAfterBootUp) {
  device().inject_fault("magnet_lost", true);
  device().power_off();
  h().power_on();
  h().run_ticks(1);
  EXPECT_EQ(h().take(), (Frames{Frame(0x705, {0x00}), emcy({0x00, 0xFF, 0x21})}));
}

class LiteralRegister : public Hlt1100Test {
 protected:
  LiteralRegister() : Hlt1100Test({{"error_register_generic_bit", "off"}, {"hold_last_on_error", "off"}}) {}
};

TEST_F(LiteralRegister, Bit5OnlyAndZeroWhileMissing) {
  device().inject_fault("magnet_lost", true);
  h().run_ms(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0xFF, 0x20})});
  EXPECT_EQ(read_i32(0x6020, 1), 0);
}

}  // namespace
}  // namespace hlt1100::test
