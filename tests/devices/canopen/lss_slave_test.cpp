// LSS slave (CiA 305), frame level: master 0x7E5 → slave 0x7E4.
#include "devices/canopen/lss_slave.h"
#include "devices/canopen/store_restore.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

namespace {
class LssTest : public ::testing::Test {
 protected:
  explicit LssTest(std::uint8_t node_id = 5) : h(vtest::make_generic_od(), {}, node_id) {
    h.node().enable_lss(canopen::LssPolicy{});
    h.power_on();
    h.take();
  }
  Frames lss(std::initializer_list<std::uint8_t> bytes) {
    std::vector<std::uint8_t> d(bytes);
    d.resize(8, 0);
    h.send(Frame(0x7E5, d));
    return h.take();
  }
  static Frame reply(std::initializer_list<std::uint8_t> bytes) {
    std::vector<std::uint8_t> d(bytes);
    d.resize(8, 0);
    return Frame(0x7E4, d);
  }
  vtest::CanopenHarness h;
};
}  // namespace

TEST_F(LssTest, ConfigureNodeIdStoreAndApplyOnResetCommunication) {
  EXPECT_TRUE(lss({0x11, 12}).empty());  // waiting: configure ignored
  EXPECT_TRUE(lss({0x04, 0x01}).empty());
  EXPECT_EQ(lss({0x11, 12}), Frames{reply({0x11, 0x00, 0x00})});
  EXPECT_EQ(lss({0x11, 0}), Frames{reply({0x11, 0x01, 0x00})});
  EXPECT_EQ(lss({0x11, 128}), Frames{reply({0x11, 0x01, 0x00})});
  EXPECT_EQ(lss({0x5E}), Frames{reply({0x5E, 5})});  // still the active ID
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
  lss({0x04, 0x00});
  h.nmt(0x82, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x70C, {0x00})});
  EXPECT_EQ(h.node().node_id(), 12);
  // Stored: survives a power cycle.
  h.node().power_off();
  h.power_on();
  EXPECT_EQ(h.node().node_id(), 12);
}

TEST_F(LssTest, InquireIdentity) {
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x5A}), Frames{reply({0x5A, 0x78, 0x56, 0x34, 0x12})});
  EXPECT_EQ(lss({0x5B}), Frames{reply({0x5B, 0x42, 0, 0, 0})});
  EXPECT_EQ(lss({0x5C}), Frames{reply({0x5C, 0x02, 0x00, 0x01, 0x00})});
  EXPECT_EQ(lss({0x5D}), Frames{reply({0x5D, 0xEE, 0xFF, 0xC0, 0x00})});
}

TEST_F(LssTest, SwitchSelectiveNeedsAllFourInOrder) {
  EXPECT_TRUE(lss({0x40, 0x78, 0x56, 0x34, 0x12}).empty());
  EXPECT_TRUE(lss({0x41, 0x42, 0, 0, 0}).empty());
  EXPECT_TRUE(lss({0x42, 0x02, 0x00, 0x01, 0x00}).empty());
  EXPECT_EQ(lss({0x43, 0xEE, 0xFF, 0xC0, 0x00}), Frames{reply({0x44})});
  EXPECT_EQ(h.node().lss()->state(), canopen::LssSlave::State::Configuration);
  lss({0x04, 0x00});
  // Wrong serial: no answer, stays waiting.
  lss({0x40, 0x78, 0x56, 0x34, 0x12});
  lss({0x41, 0x42, 0, 0, 0});
  lss({0x42, 0x02, 0x00, 0x01, 0x00});
  EXPECT_TRUE(lss({0x43, 0xEF, 0xFF, 0xC0, 0x00}).empty());
  EXPECT_EQ(h.node().lss()->state(), canopen::LssSlave::State::Waiting);
}

TEST_F(LssTest, BitTimingConfigureAndActivate) {
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x13, 0x00, 0x04}), Frames{reply({0x13, 0x00, 0x00})});
  EXPECT_EQ(lss({0x13, 0x00, 0x05}), Frames{reply({0x13, 0x01, 0x00})});  // table index 5 reserved
  EXPECT_EQ(lss({0x13, 0x01, 0x04}), Frames{reply({0x13, 0x01, 0x00})});  // table selector ≠ 0
  EXPECT_TRUE(lss({0x15, 100, 0}).empty());
  // Silent for 2 × delay; the new rate is active after the first delay.
  EXPECT_TRUE(lss({0x5E}).empty());
  h.run_ms(101);
  EXPECT_EQ(h.node().lss()->active_bit_rate(), 4);
  h.run_ms(100);
  EXPECT_EQ(lss({0x5E}), Frames{reply({0x5E, 5})});
}

TEST_F(LssTest, IdentifyRemoteSlaveByRanges) {
  lss({0x46, 0x78, 0x56, 0x34, 0x12});
  lss({0x47, 0x42, 0, 0, 0});
  lss({0x48, 0x00, 0x00, 0x00, 0x00});
  lss({0x49, 0xFF, 0xFF, 0xFF, 0xFF});
  lss({0x4A, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(lss({0x4B, 0xFF, 0xFF, 0xFF, 0x00}), Frames{reply({0x4F})});
  lss({0x46, 0x78, 0x56, 0x34, 0x12});
  lss({0x47, 0x42, 0, 0, 0});
  lss({0x48, 0x00, 0x00, 0x00, 0x00});
  lss({0x49, 0x00, 0x00, 0x01, 0x00});
  lss({0x4A, 0x00, 0x00, 0x00, 0x00});
  EXPECT_TRUE(lss({0x4B, 0x00, 0x00, 0x00, 0x00}).empty());  // serial outside range
}

namespace {
class UnconfiguredLssTest : public LssTest {
 protected:
  UnconfiguredLssTest() : LssTest(0xFF) {}
};
}  // namespace

TEST_F(UnconfiguredLssTest, SilentUntilConfiguredThenBoots) {
  EXPECT_EQ(h.node().node_id(), 0xFF);
  h.nmt(0x01, 0);
  h.send(0x600 + 5, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(h.take().empty());
  EXPECT_EQ(lss({0x4C}), Frames{reply({0x50})});
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x11, 7}), Frames{reply({0x11, 0x00, 0x00})});
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
  lss({0x04, 0x00});  // transition 4: boots with node-ID 7
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x707, {0x00})});
}

TEST_F(UnconfiguredLssTest, FastscanFindsTheSlave) {
  EXPECT_EQ(lss({0x51, 0, 0, 0, 0, 0x80, 0, 0}), Frames{reply({0x4F})});
  // Vendor 0x12345678 bit by bit would take 32 steps; check the high bit and the full match.
  EXPECT_EQ(lss({0x51, 0x00, 0x00, 0x00, 0x00, 31, 0, 0}), Frames{reply({0x4F})});  // bit 31 = 0 matches
  EXPECT_TRUE(lss({0x51, 0x00, 0x00, 0x00, 0x80, 31, 0, 0}).empty());
  EXPECT_EQ(lss({0x51, 0x78, 0x56, 0x34, 0x12, 0, 0, 1}), Frames{reply({0x4F})});
  EXPECT_EQ(lss({0x51, 0x42, 0, 0, 0, 0, 1, 2}), Frames{reply({0x4F})});
  EXPECT_EQ(lss({0x51, 0x02, 0x00, 0x01, 0x00, 0, 2, 3}), Frames{reply({0x4F})});
  EXPECT_EQ(lss({0x51, 0xEE, 0xFF, 0xC0, 0x00, 0, 3, 0}), Frames{reply({0x4F})});
  EXPECT_EQ(h.node().lss()->state(), canopen::LssSlave::State::Configuration);
}

TEST_F(LssTest, NodeIdFFCanBeRefusedAndStoreFailureHasAConfigurableAnswer) {
  h.node().lss()->policy().accept_unconfigured_node_id = false;
  h.node().lss()->policy().store_error_code = 0x02;
  h.node().lss()->policy().store_error_specific = 0x00;
  lss({0x04, 0x01});
  EXPECT_EQ(lss({0x11, 0xFF}), Frames{reply({0x11, 0x01, 0x00})});
  EXPECT_EQ(lss({0x11, 0x7F}), Frames{reply({0x11, 0x00, 0x00})});
  h.node().store().set_failing(true);
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x02, 0x00})});
  h.node().store().set_failing(false);
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0x00, 0x00})});
}

TEST_F(LssTest, StoreAnswerCanComeAfterASilentDelay) {
  h.node().lss()->policy().store_answer_delay = sim::milliseconds(300);
  ASSERT_EQ(h.write(0x1017, 0, 100, 2), 0u);  // heartbeat: shows the silence
  h.take();
  lss({0x04, 0x01});
  ASSERT_EQ(lss({0x11, 12}), Frames{reply({0x11, 0x00, 0x00})});
  EXPECT_TRUE(lss({0x17}).empty());
  h.run_ms(299);
  EXPECT_TRUE(h.take().empty());  // no answer, no heartbeat
  h.run_ms(2);
  const Frames after = h.take();
  ASSERT_FALSE(after.empty());
  EXPECT_EQ(after.front(), reply({0x17, 0x00, 0x00}));
  // A failed store is answered at once.
  h.node().store().set_failing(true);
  EXPECT_EQ(lss({0x17}), Frames{reply({0x17, 0xFF, 0x02})});
}

TEST(LssServices, ConfigurationServicesWithoutTheProtocol) {
  canopen::NodePolicy policy;
  policy.store.path = "/tmp/vplant-lss-services-" + std::to_string(::getpid());
  vtest::CanopenHarness h(vtest::make_generic_od(), policy, 5);
  h.node().enable_lss(canopen::LssPolicy{});
  h.power_on();
  auto& lss_slave = *h.node().lss();
  EXPECT_EQ(lss_slave.configure_node_id(0), 0x01);
  EXPECT_EQ(lss_slave.configure_node_id(9), 0x00);
  EXPECT_EQ(lss_slave.configure_bit_rate(5), 0x01);  // reserved in the default table
  EXPECT_EQ(lss_slave.configure_bit_rate(4), 0x00);
  EXPECT_TRUE(lss_slave.store_configuration());
  h.node().power_off();
  h.node().set_pending_node_id(5);  // forget the RAM copy: the node-ID must come from the file
  h.take();
  h.power_on();
  EXPECT_EQ(h.take(), Frames{Frame(0x709, {0x00})});
  EXPECT_EQ(lss_slave.active_bit_rate(), 4);
  std::remove(policy.store.path.c_str());
}

TEST(LssSlave, WiredFromAboveAsksToApplyTheConfiguredNodeId) {
  vtest::FakeNodeLinks links;
  links.status.node_id = canopen::kUnconfiguredNodeId;
  links.status.pending_node_id = canopen::kUnconfiguredNodeId;
  const auto od = vtest::make_generic_od();
  canopen::ParameterStore memory;
  canopen::LssSlave lss({}, od, links.status, memory, links, links, links);
  lss.power_on();
  lss.on_frame(Frame(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0}).to_can(), sim::Time{});  // configuration
  lss.on_frame(Frame(0x7E5, {0x11, 0x0A, 0, 0, 0, 0, 0, 0}).to_can(), sim::Time{});  // node-ID 10
  lss.on_frame(Frame(0x7E5, {0x17, 0, 0, 0, 0, 0, 0, 0}).to_can(), sim::Time{});     // store
  EXPECT_EQ(links.pending_node_ids, std::vector<std::uint8_t>{0x0A});
  EXPECT_EQ(links.node_id_applied, 0);
  lss.on_frame(Frame(0x7E5, {0x04, 0x00, 0, 0, 0, 0, 0, 0}).to_can(), sim::Time{});  // waiting
  EXPECT_EQ(links.node_id_applied, 1);
  EXPECT_EQ(links.sent, (Frames{Frame(0x7E4, {0x11, 0, 0, 0, 0, 0, 0, 0}), Frame(0x7E4, {0x17, 0, 0, 0, 0, 0, 0, 0})}));
}
