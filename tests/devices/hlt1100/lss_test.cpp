// HLT 1100 LSS (the only way to set node-ID and bit rate). The manual prints command specifiers
// in decimal: 4, 17, 19, 21, 23, 64-67, 70-76, 81, 90-94 are 0x04, 0x11, 0x13, 0x15, 0x17,
// 0x40-0x43, 0x46-0x4C, 0x51, 0x5A-0x5E (digest checklist 32-38; test vectors 38-50).
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

Frame reply(std::initializer_list<std::uint8_t> bytes) { return Frame(0x7E4, eight(bytes)); }

class Lss : public Hlt1100Test {
 protected:
  explicit Lss(std::map<std::string, std::string> settings = {}, std::uint8_t node_id = 5)
      : Hlt1100Test(std::move(settings), node_id) {}
  Frames lss(std::initializer_list<std::uint8_t> bytes) {
    h().send(Frame(0x7E5, eight(bytes)));
    return h().take();
  }
  void u32(std::uint8_t cs, std::uint32_t v) {
    lss({cs, static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16),
         static_cast<std::uint8_t>(v >> 24)});
  }
  Frames u32_reply(std::uint8_t cs, std::uint32_t v) {
    return lss({cs, static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16),
                static_cast<std::uint8_t>(v >> 24)});
  }
  canopen::LssSlave::State state() { return device().node().lss()->state(); }
  const Settings& s() { return device().settings(); }
};

TEST_F(Lss, ConfigurationServicesAreIgnoredInWaiting) {
  EXPECT_TRUE(lss({0x11, 0x0C}).empty());
  EXPECT_TRUE(lss({0x13, 0x00, 0x04}).empty());
  EXPECT_TRUE(lss({0x17}).empty());
  EXPECT_TRUE(lss({0x5A}).empty());
  EXPECT_TRUE(lss({0x04, 0x01}).empty());
  EXPECT_EQ(lss({0x5A}), Frames{reply({0x5A, 0xDA, 0x00, 0x00, 0x00})});
  EXPECT_EQ(lss({0x5B}), Frames{reply({0x5B, 0x00, 0x11, 0x00, 0x00})});
  EXPECT_EQ(lss({0x5C}), Frames{reply({0x5C, 0x04, 0x00, 0x01, 0x00})});
  EXPECT_EQ(lss({0x5D}), Frames{reply({0x5D, 0x01, 0x00, 0x00, 0x00})});
}

TEST_F(Lss, NodeIdTakesEffectAtResetCommunication) {
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x11, 0x0C}), Frames{reply({0x11, 0x00, 0x00})});
  EXPECT_EQ(lss({0x5E}), Frames{reply({0x5E, 0x05})});  // still the old ID [M §4.7.5.5]
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
  h().nmt(0x82, 5);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x70C, {0x00})});
  h().send(0x60C, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(h().take(), Frames{Frame(0x58C, eight({0x43, 0x00, 0x10, 0x00, 0x96, 0x01, 0x0A, 0x00}))});
  EXPECT_EQ(lss({0x5E}), Frames{reply({0x5E, 0x0C})});
  // Stored: kept over a power cycle; the EMCY and PDO COB-IDs follow.
  power_cycle();
  EXPECT_EQ(h().take(), Frames{Frame(0x70C, {0x00})});
  h().nmt(0x01, 12);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x18C, {0xE8, 0x03, 0x00, 0x00})});
}

TEST_F(Lss, ConfigureErrors) {
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x11, 0x00}), Frames{reply({0x11, 0x01, 0x00})});
  EXPECT_EQ(lss({0x11, 0x80}), Frames{reply({0x11, 0x01, 0x00})});
  for (std::uint8_t bad : {5, 8, 9}) EXPECT_EQ(lss({0x13, 0x00, bad}), Frames{reply({0x13, 0x01, 0x00})}) << int(bad);
  EXPECT_EQ(lss({0x13, 0x01, 0x04}), Frames{reply({0x13, 0x01, 0x00})});
  for (std::uint8_t good : {0, 1, 2, 3, 4, 6, 7}) EXPECT_EQ(lss({0x13, 0x00, good}), Frames{reply({0x13, 0x00, 0x00})});
}

TEST_F(Lss, ActivateBitTimingSwitchesAfterTheDelayAndKeepsTheNmtState) {
  h().bus().set_bit_rate_kbit(250);
  start();
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x13, 0x00, 0x04}), Frames{reply({0x13, 0x00, 0x00})});  // 125 kbit/s
  lss({0x15, 0x64, 0x00});                                                  // 100 ms
  h().send(Frame::remote(0x705, 1));
  h().run_ms(199);
  EXPECT_TRUE(h().take().empty());
  h().bus().set_bit_rate_kbit(125);  // the master follows
  h().run_ms(2);
  h().send(Frame::remote(0x705, 1));
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x05})});  // Operational, at 125 kbit/s
  // Not stored: a power cycle brings back 250 kbit/s.
  power_cycle();
  EXPECT_TRUE(h().take().empty());
  h().bus().set_bit_rate_kbit(250);
  EXPECT_EQ(h().read_u(0x1000, 0), 0x000A0196u);
  // Stored (at the new rate): kept.
  lss({0x04, 0x01});
  lss({0x13, 0x00, 0x04});
  lss({0x15, 0x0A, 0x00});
  h().run_ms(21);
  h().bus().set_bit_rate_kbit(125);
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
  power_cycle();
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});
}

TEST_F(Lss, SwitchSelectiveNeedsTheExactAddress) {
  u32(0x40, kVendorId);
  u32(0x41, s().product_code);
  u32(0x42, s().revision);
  EXPECT_EQ(u32_reply(0x43, s().serial), Frames{reply({0x44})});
  EXPECT_EQ(state(), canopen::LssSlave::State::Configuration);
  lss({0x04, 0x00});
  u32(0x40, kVendorId);
  u32(0x41, s().product_code + 1);
  u32(0x42, s().revision);
  EXPECT_TRUE(u32_reply(0x43, s().serial).empty());
  EXPECT_EQ(state(), canopen::LssSlave::State::Waiting);
}

TEST_F(Lss, IdentifyRemoteSlaveByRangesInBothStates) {
  for (int config = 0; config < 2; ++config) {
    lss({0x04, static_cast<std::uint8_t>(config)});
    u32(0x46, kVendorId);
    u32(0x47, s().product_code);
    u32(0x48, 0x00000000);
    u32(0x49, 0xFFFFFFFF);
    u32(0x4A, 0x00000000);
    EXPECT_EQ(u32_reply(0x4B, 0xFFFFFFFF), Frames{reply({0x4F})});
    u32(0x46, kVendorId);
    u32(0x47, s().product_code);
    u32(0x48, 0x00000000);
    u32(0x49, 0xFFFFFFFF);
    u32(0x4A, s().serial + 1);
    EXPECT_TRUE(u32_reply(0x4B, 0xFFFFFFFF).empty());
  }
}

TEST_F(Lss, ConfiguredNodesIgnoreNonConfiguredIdentifyAndFastscan) {
  EXPECT_TRUE(lss({0x4C}).empty());
  EXPECT_TRUE(lss({0x51, 0, 0, 0, 0, 0x80, 0, 0}).empty());
}

class UnconfiguredLss : public Lss {
 protected:
  UnconfiguredLss() : Lss({}, 0xFF) {}
};

TEST_F(UnconfiguredLss, AnswersOnlyLssThenBootsWithTheStoredNodeId) {
  EXPECT_TRUE(h().take().empty());  // no boot-up
  h().nmt(0x01, 0);
  h().send(0x6FF, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  h().send(Frame::remote(0x77F, 1));
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(lss({0x4C}), Frames{reply({0x50})});
  // Fastscan: reset, then each of the four parts matched in full.
  EXPECT_EQ(lss({0x51, 0, 0, 0, 0, 0x80, 0, 0}), Frames{reply({0x4F})});
  auto part = [&](std::uint32_t v, std::uint8_t sub, std::uint8_t next) {
    return lss({0x51, static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v >> 16),
                static_cast<std::uint8_t>(v >> 24), 0, sub, next});
  };
  EXPECT_TRUE(part(kVendorId + 1, 0, 1).empty());
  EXPECT_EQ(part(kVendorId, 0, 1), Frames{reply({0x4F})});
  EXPECT_EQ(part(s().product_code, 1, 2), Frames{reply({0x4F})});
  EXPECT_EQ(part(s().revision, 2, 3), Frames{reply({0x4F})});
  EXPECT_EQ(part(s().serial, 3, 0), Frames{reply({0x4F})});
  EXPECT_EQ(state(), canopen::LssSlave::State::Configuration);
  EXPECT_EQ(lss({0x11, 0x0C}), Frames{reply({0x11, 0x00, 0x00})});
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
  lss({0x04, 0x00});  // transition 4
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x70C, {0x00})});
}

TEST_F(UnconfiguredLss, WaitingWithoutStoreStaysUnconfigured) {
  lss({0x04, 0x01});
  lss({0x11, 0x0C});
  lss({0x04, 0x00});
  h().run_ms(10);
  EXPECT_TRUE(h().take().empty());
}

class LssNotInOperational : public Lss {
 protected:
  LssNotInOperational() : Lss({{"lss_in_operational", "off"}}) {}
};

TEST_F(LssNotInOperational, KnobIgnoresLssWhileOperational) {
  start();
  EXPECT_TRUE(lss({0x04, 0x01}).empty());
  EXPECT_TRUE(lss({0x5A}).empty());
  h().nmt(0x80, 5);
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x5A}), Frames{reply({0x5A, 0xDA})});
}

class LssBitRate : public Lss {
 protected:
  LssBitRate() : Lss({{"bit_rate_kbit", "500"}}) {}
};

TEST_F(LssBitRate, FactoryBitRateSetting) { EXPECT_EQ(device().node().bit_rate_kbit(), 500u); }

}  // namespace
}  // namespace hlt1100::test
