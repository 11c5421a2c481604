// Heartbeat producer, node guarding, life guarding (node 5), frame level.
#include "devices/canopen/error_control.h"

#include <gtest/gtest.h>

#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

TEST(Heartbeat, ProducedAtThe1017Period) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.take();
  ASSERT_EQ(h.write(0x1800, 1, 0x80000185u, 4), 0u);  // keep the event TPDO out of the way
  ASSERT_EQ(h.write(0x1017, 0, 100, 2), 0u);
  h.take_times();
  h.run_ms(350);
  const auto times = h.take_times();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ((times[1] - times[0]).count(), 100000);
  EXPECT_EQ((times[2] - times[1]).count(), 100000);
  h.nmt(0x01, 5);
  h.take();
  h.run_ms(100);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x05})});
  h.nmt(0x02, 5);
  h.take();
  h.run_ms(100);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x04})});  // heartbeat continues in Stopped
  ASSERT_EQ(h.node().nmt_state(), canopen::NmtState::Stopped);
  h.nmt(0x80, 5);
  ASSERT_EQ(h.write(0x1017, 0, 0, 2), 0u);
  h.take();
  h.run_ms(500);
  EXPECT_TRUE(h.take().empty());
}

TEST(NodeGuarding, ToggleBitAlternatesAndResetsWithCommunication) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.take();
  h.send(Frame::remote(0x705, 1));
  h.send(Frame::remote(0x705, 1));
  h.nmt(0x01, 5);
  h.send(Frame::remote(0x705, 1));
  EXPECT_EQ(h.take(), (Frames{Frame(0x705, {0x7F}), Frame(0x705, {0xFF}), Frame(0x705, {0x05})}));
  h.nmt(0x82, 5);
  h.run_ticks(1);
  h.take();
  h.send(Frame::remote(0x705, 1));
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x7F})});
  // A data frame on 0x705 is not a guard request.
  h.send(0x705, {0x00});
  EXPECT_TRUE(h.take().empty());
}

TEST(LifeGuarding, TimeoutRaisesEmcyAndRecoveryClearsIt) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(h.write(0x100D, 0, 3, 1), 0u);
  ASSERT_EQ(h.write(0x1029, 1, 1, 1), 0u);  // no state change on communication errors
  h.send(Frame::remote(0x705, 1));  // arms life guarding
  h.take();
  h.run_ms(300);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x30, 0x81, 0x11, 0, 0, 0, 0, 0})});
  h.run_ms(1000);
  EXPECT_TRUE(h.take().empty());  // one EMCY per event
  h.send(Frame::remote(0x705, 1));
  EXPECT_EQ(h.take(), (Frames{Frame(0x705, {0xFF}), Frame(0x085, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0})}));
}

TEST(LifeGuarding, ErrorBehaviourGoesPreOperationalFromOperational) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x100C, 0, 10, 2), 0u);
  ASSERT_EQ(h.write(0x100D, 0, 2, 1), 0u);
  h.nmt(0x01, 5);
  h.send(Frame::remote(0x705, 1));
  h.run_ms(30);
  EXPECT_EQ(h.node().nmt_state(), canopen::NmtState::PreOperational);  // 0x1029:01 = 0
}

TEST(BusOff, RecoverySendsEmcy8140OnceAndAppliesTheErrorBehaviour) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  h.node().communication_error(canopen::CommError::BusOffRecovered);
  h.run_ms(5);
  // An event: EMCY 8140h with the communication bit, no "no error" EMCY after it.
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x40, 0x81, 0x11, 0, 0, 0, 0, 0})});
  EXPECT_EQ(h.read_u(0x1003, 1), 0x8140u);
  EXPECT_EQ(h.node().nmt_state(), canopen::NmtState::PreOperational);  // 0x1029:01 = 0
}

TEST(LifeGuarding, HeartbeatDisarmsLifeGuardingWhenGuardingIsExclusive) {
  canopen::NodePolicy policy;
  policy.error_control.guard_while_heartbeat = false;
  vtest::CanopenHarness h(vtest::make_generic_od(), policy, 5);
  h.power_on();
  h.take();
  ASSERT_EQ(h.write(0x1800, 1, 0x80000185u, 4), 0u);
  ASSERT_EQ(h.write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(h.write(0x100D, 0, 3, 1), 0u);
  h.send(Frame::remote(0x705, 1));  // arms life guarding (300 ms)
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x7F})});
  ASSERT_EQ(h.write(0x1017, 0, 1000, 2), 0u);  // heartbeat replaces guarding
  h.send(Frame::remote(0x705, 1));
  EXPECT_TRUE(h.take().empty());  // not answered
  h.run_ms(900);
  EXPECT_TRUE(h.take().empty());  // no life-guarding EMCY: guarding is off while the heartbeat runs
  EXPECT_FALSE(h.node().error_control().life_guarding_armed());
}

TEST(ErrorControl, WiredFromAboveReportsTheLifeGuardingTimeout) {
  vtest::FakeNodeLinks links;
  links.status.node_id = 5;
  links.status.nmt_state = canopen::NmtState::PreOperational;
  auto od = vtest::make_generic_od();
  od.set<std::uint16_t>(0x100C, 0, 100);
  od.set<std::uint8_t>(0x100D, 0, 3);
  canopen::ErrorControlPolicy policy;
  canopen::ErrorControl ec(od, policy, links.status, links, links);
  ec.bind_objects();
  ec.reset_communication(sim::Time{});
  ec.on_frame(Frame::remote(0x705, 1).to_can(), sim::Time{});
  EXPECT_EQ(links.sent, Frames{Frame(0x705, {0x7F})});
  ec.process(sim::Time{} + sim::milliseconds(300));
  EXPECT_TRUE(links.comm_errors.empty());
  ec.process(sim::Time{} + sim::milliseconds(301));
  EXPECT_EQ(links.comm_errors, (std::vector<std::pair<canopen::CommError, std::uint32_t>>{{canopen::CommError::LifeGuarding, 300}}));
}
