#include "devices/canopen/emergency.h"

#include <gtest/gtest.h>

#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

namespace {
class EmcyTest : public ::testing::Test {
 protected:
  EmcyTest() : h(vtest::make_generic_od(), {}, 5) {
    h.power_on();
    h.take();
  }
  canopen::Emergency& emcy() { return h.node().emergency(); }
  vtest::CanopenHarness h;
};
}  // namespace

TEST_F(EmcyTest, OneFramePerRisingEdgeAndNoErrorAtTheEnd) {
  emcy().raise(0x2310, 0x03, {0xAA, 0xBB, 0, 0, 0});
  emcy().raise(0x2310, 0x03);  // still active: no repetition
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x10, 0x23, 0x03, 0xAA, 0xBB, 0, 0, 0})});
  EXPECT_EQ(h.read_u(0x1001, 0), 0x03u);
  emcy().raise(0x3120, 0x05);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x20, 0x31, 0x07, 0, 0, 0, 0, 0})});
  emcy().clear(0x2310);
  EXPECT_TRUE(h.take().empty());  // another error still active
  EXPECT_EQ(h.read_u(0x1001, 0), 0x05u);
  emcy().clear(0x3120);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST_F(EmcyTest, HistoryNewestFirstClearedByWritingZero) {
  emcy().raise(0x1000, 0x01, {0x34, 0x12, 0, 0, 0});
  emcy().raise(0x2000, 0x03);
  EXPECT_EQ(h.read_u(0x1003, 0), 2u);
  EXPECT_EQ(h.read_u(0x1003, 1), 0x00002000u);
  EXPECT_EQ(h.read_u(0x1003, 2), 0x12341000u);
  std::uint32_t abort = 0;
  EXPECT_FALSE(h.read(0x1003, 3, &abort));
  EXPECT_EQ(abort, 0x08000024u);
  EXPECT_EQ(h.write(0x1003, 0, 0, 1), 0u);
  EXPECT_EQ(h.read_u(0x1003, 0), 0u);
  EXPECT_EQ(h.write(0x1003, 0, 1, 1), 0x06090030u);
}

TEST_F(EmcyTest, InhibitTimeQueuesFrames) {
  ASSERT_EQ(h.write(0x1015, 0, 100, 2), 0u);  // 10 ms
  emcy().raise(0x1000, 0x01);
  emcy().raise(0x2000, 0x01);
  EXPECT_EQ(h.take().size(), 1u);
  h.run_ms(9);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x00, 0x20, 0x01, 0, 0, 0, 0, 0})});
}

TEST_F(EmcyTest, DisabledByCobIdBit31AndSilentInStopped) {
  h.nmt(0x02, 5);
  emcy().raise(0x1000, 0x01);
  EXPECT_TRUE(h.take().empty());
  h.nmt(0x80, 5);
  h.run_ms(5);
  EXPECT_TRUE(h.take().empty());  // never sent late
  EXPECT_EQ(h.read_u(0x1003, 1), 0x1000u);  // but recorded
  ASSERT_EQ(h.write(0x1014, 0, 0x80000085u, 4), 0u);
  emcy().raise(0x2000, 0x01);
  EXPECT_TRUE(h.take().empty());
}

TEST_F(EmcyTest, PresentErrorsHistoryMode) {
  h.node().policy().emcy.history = canopen::EmcyPolicy::History::PresentErrors;
  emcy().raise(0x1000, 0x01);
  emcy().raise(0x2000, 0x01);
  emcy().clear(0x1000);
  EXPECT_EQ(h.read_u(0x1003, 0), 1u);
  EXPECT_EQ(h.read_u(0x1003, 1), 0x2000u);
}

TEST(EmcyHistoryOff, DepthZeroLeaves1003ToTheDevice) {
  canopen::NodePolicy p;
  p.emcy.history_depth = 0;
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  h.take();
  h.node().od().set<std::uint8_t>(0x1003, 0, 3);  // the device's own bookkeeping
  h.node().emergency().raise(0x5000, 0x01);
  EXPECT_EQ(h.take(), Frames{Frame(0x85, {0x00, 0x50, 0x01, 0, 0, 0, 0, 0})});
  h.node().emergency().reset_communication();
  EXPECT_EQ(h.node().od().get<int>(0x1003, 0), 3);
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x1003, 1), 0u);
}

TEST(EmcyPolicyKnobs, NoEmcyInPreOperationalWhenTheManualSaysSo) {
  canopen::NodePolicy policy;
  policy.emcy.send_in_preoperational = false;
  vtest::CanopenHarness h(vtest::make_generic_od(), policy, 5);
  h.power_on();
  h.take();
  h.node().emergency().raise(0x5000, 0x81);
  h.run_ms(5);
  EXPECT_TRUE(h.take().empty());
  EXPECT_EQ(h.read_u(0x1001, 0), 0x81u);  // recorded all the same
  EXPECT_EQ(h.read_u(0x1003, 1), 0x5000u);
  h.nmt(0x01, 5);
  h.run_ms(1);
  h.take();
  h.node().emergency().raise(0x6000, 0x81);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x00, 0x60, 0x81, 0, 0, 0, 0, 0})});
}

TEST(Emergency, WiredFromAboveSendsThroughItsSender) {
  vtest::FakeNodeLinks links;
  links.status.node_id = 5;
  links.status.nmt_state = canopen::NmtState::PreOperational;
  auto od = vtest::make_generic_od();
  od.reset_range(0x1000, 0x1FFF, 5);  // node-relative COB-IDs for node 5
  canopen::EmcyPolicy policy;
  canopen::Emergency emcy(od, policy, links.status, links);
  emcy.bind_objects();
  emcy.raise(0x2310, 0x03);
  EXPECT_EQ(links.sent, Frames{Frame(0x085, {0x10, 0x23, 0x03, 0, 0, 0, 0, 0})});
  links.status.nmt_state = canopen::NmtState::Stopped;  // no EMCY in Stopped
  emcy.raise(0x3120, 0x05);
  EXPECT_EQ(links.sent.size(), 1u);
}
