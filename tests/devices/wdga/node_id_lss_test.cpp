// WDGA node-ID and bit rate by SDO (2100h/2101h) and LSS, COB-ID freezing, store/restore and
// customer data (digest checklist 12-16, 38, 39; vectors W1-W3, W19-W21, §5.6).
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

Frame reply(std::initializer_list<std::uint8_t> bytes) { return Frame(0x7E4, eight(bytes)); }

class NodeId : public WdgaTest {
 protected:
  Frames lss(std::initializer_list<std::uint8_t> bytes) {
    h().send(Frame(0x7E5, eight(bytes)));
    return h().take();
  }
  void reset_node() {
    h().nmt(0x81, id());
    h().run_ticks(1);
  }
};

TEST_F(NodeId, SdoNodeIdIsPendingUntilAResetAndSavedAtOnce) {
  EXPECT_EQ(sdo({0x2F, 0x01, 0x21, 0x00, 0x05}), resp({0x60, 0x01, 0x21, 0x00}));
  EXPECT_EQ(u(0x2101), 5u);
  EXPECT_EQ(sdo({0x40, 0x00, 0x10, 0x00})->id, 0x5FFu);  // still 127
  reset_node();
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(u(0x1800, 1), 0x40000185u);
  EXPECT_EQ(u(0x1014), 0x85u);
  // The frames themselves move to the new node-ID.
  start();
  h().take();
  turn_to(0.25);
  h().run_ms(3);
  const auto frames = h().take();
  ASSERT_FALSE(frames.empty());
  for (const auto& f : frames) EXPECT_EQ(f.id, 0x185u);
  device().inject_fault("can_overrun", true);
  EXPECT_EQ(h().take(), Frames{Frame(0x085, eight({0x10, 0x81, 0x10, 0x01}))});
  power_cycle();
  EXPECT_EQ(id(), 5);
}

TEST_F(NodeId, RangeAndStateChecks) {
  EXPECT_EQ(h().write(0x2101, 0, 0, 1), 0x06090030u);
  EXPECT_EQ(h().write(0x2101, 0, 128, 1), 0x06090030u);
  EXPECT_EQ(h().write(0x2100, 0, 10, 1), 0x06090030u);
  start();
  EXPECT_EQ(sdo({0x2F, 0x01, 0x21, 0x00, 0x05}), resp({0x80, 0x01, 0x21, 0x00, 0x22, 0x00, 0x00, 0x08}));
  EXPECT_EQ(h().write(0x2100, 0, 3, 1), 0x08000022u);
}

TEST_F(NodeId, StoredCobIdsNoLongerFollowTheNodeId) {
  ASSERT_EQ(h().write(0x2101, 0, 5, 1), 0u);
  reset_node();
  h().take();
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65}), resp({0x60, 0x10, 0x10, 0x01}));
  ASSERT_EQ(h().write(0x2101, 0, 6, 1), 0u);
  reset_node();
  EXPECT_EQ(h().take(), Frames{Frame(0x706, {0x00})});
  EXPECT_EQ(u(0x1800, 1), 0x40000185u);  // frozen
  EXPECT_EQ(u(0x1014), 0x85u);
  // On the bus: started and turned, TPDO1 on `tpdo`; an overrun (an event, no state change)
  // sends its EMCY on `emcy`.
  auto expect_on_the_bus = [&](double turn, std::uint32_t tpdo, std::uint32_t emcy) {
    start();
    h().take();
    turn_to(turn);
    h().run_ms(3);
    const auto frames = h().take();
    ASSERT_FALSE(frames.empty());
    for (const auto& f : frames) EXPECT_EQ(f.id, tpdo);
    device().inject_fault("can_overrun", true);
    EXPECT_EQ(h().take(), Frames{Frame(emcy, eight({0x10, 0x81, 0x10, 0x01}))});
  };
  expect_on_the_bus(0.25, 0x185, 0x085);  // still the stored COB-IDs
  h().nmt(0x80, 6);
  ASSERT_EQ(h().write(0x1011, 1, kLoad, 4), 0u);
  reset_node();
  EXPECT_EQ(h().take(), Frames{Frame(0x706, {0x00})});
  EXPECT_EQ(u(0x1800, 1), 0x40000186u);  // tracking again
  EXPECT_EQ(u(0x1014), 0x86u);
  expect_on_the_bus(0.5, 0x186, 0x086);
}

TEST_F(NodeId, StoreSignatureAndRestoreKeepsNodeIdBitRateAndCustomerData) {
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0, 0, 0, 0}), resp({0x80, 0x10, 0x10, 0x01, 0x20, 0x00, 0x00, 0x08}));
  ASSERT_EQ(h().write(0x2120, 3, 0x12345678, 4), 0u);
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  ASSERT_EQ(h().write(0x1010, 1, kSave, 4), 0u);
  ASSERT_EQ(h().write(0x2101, 0, 9, 1), 0u);
  ASSERT_EQ(h().write(0x2100, 0, 4, 1), 0u);
  EXPECT_EQ(sdo({0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64}), resp({0x60, 0x11, 0x10, 0x01}));
  EXPECT_EQ(u(0x6001), 4096u);  // the old values stay until the reset
  power_cycle();
  EXPECT_EQ(id(), 9);
  EXPECT_EQ(u(0x6001), 16384u);
  EXPECT_EQ(u(0x2100), 4u);
  EXPECT_EQ(u(0x2120, 3), 0x12345678u);
}

TEST_F(NodeId, CustomerDataIsSavedOnWrite) {
  ASSERT_EQ(h().write(0x2120, 3, 0x12345678, 4), 0u);
  power_cycle();
  EXPECT_EQ(u(0x2120, 3), 0x12345678u);
  EXPECT_EQ(u(0x2120, 4), 0xFFFFFFFFu);
}

TEST_F(NodeId, LssGlobalSequenceFromTheManual) {
  h().bus().set_bit_rate_kbit(125);  // the tool's rate, detected at boot
  power_cycle();
  h().nmt(0x02, 0x7F);
  EXPECT_TRUE(lss({0x04, 0x01}).empty());
  EXPECT_EQ(device().led(), Led::RedGreenFlicker);
  EXPECT_EQ(lss({0x13, 0x00, 0x03}), Frames{reply({0x13, 0x00, 0x00})});
  EXPECT_EQ(lss({0x11, 0x05}), Frames{reply({0x11, 0x00, 0x00})});
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
  EXPECT_TRUE(lss({0x04, 0x00}).empty());
  EXPECT_EQ(lss({0x13, 0x0A}), Frames{});  // waiting again
  device().power_off();
  h().bus().set_bit_rate_kbit(250);
  h().run_ms(10);
  device().power_on(h().now());
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});  // no detection: a fixed rate now
  EXPECT_EQ(u(0x2100), 3u);
  EXPECT_EQ(u(0x2101), 5u);
}

TEST_F(NodeId, LssErrorsAndNoLssInOperational) {
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x13, 0x00, 0x0A}), Frames{reply({0x13, 0x01})});
  EXPECT_EQ(lss({0x11, 0x80}), Frames{reply({0x11, 0x01})});
  EXPECT_EQ(lss({0x11, 0x00}), Frames{reply({0x11, 0x01})});
  EXPECT_EQ(lss({0x11, 0xFF}), Frames{reply({0x11, 0x01})});
  EXPECT_TRUE(lss({0x15, 0x64, 0x00}).empty());  // no activate bit timing
  lss({0x04, 0x00});
  EXPECT_TRUE(lss({0x51, 0, 0, 0, 0, 0x80, 0, 0}).empty());  // no fastscan
  EXPECT_TRUE(lss({0x4C}).empty());                          // always configured
  start();
  h().take();
  EXPECT_TRUE(lss({0x04, 0x01}).empty());
  EXPECT_TRUE(lss({0x5A}).empty());
  EXPECT_EQ(device().node().lss()->state(), canopen::LssSlave::State::Waiting);
}

TEST_F(NodeId, LssSelectiveAndInquire) {
  lss({0x40, 0x1F, 0x02, 0x00, 0x01});
  lss({0x41, 0x41, 0x47, 0x44, 0x57});
  lss({0x42, 0x08, 0x02, 0x06, 0x03});
  EXPECT_EQ(lss({0x43, 0x38, 0x61, 0xBC, 0x00}), Frames{reply({0x44, 0x01})});
  EXPECT_EQ(lss({0x5A}), Frames{reply({0x5A, 0x1F, 0x02, 0x00, 0x01})});
  EXPECT_EQ(lss({0x5B}), Frames{reply({0x5B, 0x41, 0x47, 0x44, 0x57})});
  EXPECT_EQ(lss({0x5C}), Frames{reply({0x5C, 0x08, 0x02, 0x06, 0x03})});
  EXPECT_EQ(lss({0x5D}), Frames{reply({0x5D, 0x38, 0x61, 0xBC, 0x00})});
  EXPECT_EQ(lss({0x5E}), Frames{reply({0x5E, 0x7F})});
  lss({0x04, 0x00});
  lss({0x40, 0x1F, 0x02, 0x00, 0x01});
  lss({0x41, 0x41, 0x47, 0x44, 0x57});
  lss({0x42, 0x08, 0x02, 0x06, 0x03});
  EXPECT_TRUE(lss({0x43, 0x39, 0x61, 0xBC, 0x00}).empty());
  // Identify remote slave.
  lss({0x46, 0x1F, 0x02, 0x00, 0x01});
  lss({0x47, 0x41, 0x47, 0x44, 0x57});
  lss({0x48, 0x00, 0x00, 0x00, 0x00});
  lss({0x49, 0xFF, 0xFF, 0xFF, 0xFF});
  lss({0x4A, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(lss({0x4B, 0xFF, 0xFF, 0xFF, 0xFF}), Frames{reply({0x4F})});
}

TEST_F(NodeId, LssStoreFailsWithAFailingEeprom) {
  device().inject_fault("eeprom_error", true);
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x02})});
  // The SDO path saves the same cells: EMCY 5000h (EEPROM timeout) and abort 0x06060000.
  h().send(0x67F, {0x2F, 0x01, 0x21, 0x00, 0x05, 0, 0, 0});
  EXPECT_EQ(h().take(), (Frames{emcy({0x00, 0x50, 0x01, 0x00, 0x08}), resp({0x80, 0x01, 0x21, 0x00, 0x00, 0x00, 0x06, 0x06})}));
  EXPECT_EQ(u(0x1002), 0x04u);
}

class VerifyConfiguration : public WdgaTest {};

TEST_F(VerifyConfiguration, AnyConfigurationChangeClearsTheStamp) {
  ASSERT_EQ(h().write(0x1020, 1, 12345, 4), 0u);
  ASSERT_EQ(h().write(0x1020, 2, 678, 4), 0u);
  ASSERT_EQ(h().write(0x1010, 1, kSave, 4), 0u);
  ASSERT_EQ(h().write(0x1003, 0, 0, 1), 0u);
  EXPECT_EQ(u(0x1020, 1), 12345u);  // saving, clearing errors: not a configuration change
  ASSERT_EQ(h().write(0x6200, 0, 5, 2), 0u);
  EXPECT_EQ(u(0x1020, 1), 0u);
  EXPECT_EQ(u(0x1020, 2), 0u);
}

}  // namespace
}  // namespace wdga::test
