#include "devices/canopen/heartbeat_consumer.h"

#include <gtest/gtest.h>

#include "devices/transition_log.h"
#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

TEST(HeartbeatConsumer, StartsAtFirstHeartbeatAndTimesOut) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x1029, 1, 1, 1), 0u);
  ASSERT_EQ(h.write(0x1016, 1, (0x20u << 16) | 150u, 4), 0u);  // node 0x20, 150 ms
  h.take();
  h.run_ms(1000);
  EXPECT_TRUE(h.take().empty());  // not monitored before the first heartbeat
  h.send(0x720, {0x05});
  h.run_ms(150);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x30, 0x81, 0x11, 0, 0, 0, 0, 0})});
  h.send(0x720, {0x05});
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0, 0, 0, 0, 0, 0, 0, 0})});
}

// The 1029h:01 reaction names the missed producer: not an NMT command.
TEST(HeartbeatConsumer, TimeoutIsTheCauseOfTheErrorBehaviour) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  devices::TransitionLog log;
  h.node().set_transition_log(&log);
  h.power_on();
  ASSERT_EQ(h.write(0x1029, 1, 0, 1), 0u);  // 0: Operational → Pre-operational
  ASSERT_EQ(h.write(0x1016, 1, (0x20u << 16) | 150u, 4), 0u);
  h.nmt(0x01, 5);
  h.send(0x720, {0x05});
  const auto before = log.last_seq();
  h.run_ms(200);
  std::vector<devices::Transition> t;
  log.for_each_after(before, [&](const devices::Transition& e) { t.push_back(e); });
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].from, "OPERATIONAL");
  EXPECT_EQ(t[0].to, "PRE-OPERATIONAL");
  EXPECT_EQ(t[0].transition, "1029h:01");
  EXPECT_EQ(t[0].cause, devices::TransitionCause::HeartbeatTimeout);
  EXPECT_EQ(t[0].value, 0x20u);
}

namespace {
canopen::ObjectDictionary od_with_two_consumers() {
  canopen::ObjectDictionary od;
  canopen::CommunicationProfile p;
  p.heartbeat_consumers = 2;
  canopen::add_communication_objects(od, p);
  return od;
}
}  // namespace

// CiA 301 §7.5.2.21: two non-zero consumer heartbeat times for the same node-ID → 0x06040043.
TEST(HeartbeatConsumer, SecondEntryForTheSameNodeIsAParameterIncompatibility) {
  vtest::CanopenHarness h(od_with_two_consumers(), {}, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x1016, 1, (0x20u << 16) | 150u, 4), 0u);
  h.take();
  h.send(0x605, {0x23, 0x16, 0x10, 0x02, 0xC8, 0x00, 0x20, 0x00});  // node 0x20 again, 200 ms
  EXPECT_EQ(h.take(), Frames{Frame(0x585, {0x80, 0x16, 0x10, 0x02, 0x43, 0x00, 0x04, 0x06})});
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x1016, 2), 0u);
  // Another node, a zero time, or rewriting the same sub-index are all fine.
  EXPECT_EQ(h.write(0x1016, 2, (0x21u << 16) | 200u, 4), 0u);
  EXPECT_EQ(h.write(0x1016, 2, (0x20u << 16) | 0u, 4), 0u);
  EXPECT_EQ(h.write(0x1016, 1, (0x20u << 16) | 300u, 4), 0u);
}

TEST(HeartbeatConsumer, DuplicateCheckCanBeSwitchedOff) {
  canopen::NodePolicy p;
  p.error_control.duplicate_consumer = canopen::SdoAbort::None;
  vtest::CanopenHarness h(od_with_two_consumers(), p, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x1016, 1, (0x20u << 16) | 150u, 4), 0u);
  EXPECT_EQ(h.write(0x1016, 2, (0x20u << 16) | 200u, 4), 0u);
}

TEST(HeartbeatConsumer, WiredFromAboveReportsTheTimeoutAndNewRoutes) {
  vtest::FakeNodeLinks links;
  auto od = vtest::make_generic_od();
  canopen::ErrorControlPolicy policy;
  canopen::HeartbeatConsumer hb(od, policy, links, links);
  hb.bind_objects();
  ASSERT_EQ(od.write(*od.entry(0x1016, 1), canopen::ObjectDictionary::encode(canopen::DataType::Unsigned32, 0x00070064),
                     canopen::Origin::Sdo),
            canopen::SdoAbort::None);
  EXPECT_EQ(links.routes_changed, 1);
  EXPECT_EQ(hb.producers(), std::vector<std::uint8_t>{7});
  hb.on_frame(Frame(0x707, {0x05}).to_can(), sim::Time{});
  hb.process(sim::Time{} + sim::milliseconds(100));
  EXPECT_TRUE(links.comm_errors.empty());
  hb.process(sim::Time{} + sim::milliseconds(101));
  EXPECT_EQ(links.comm_errors, (std::vector<std::pair<canopen::CommError, std::uint32_t>>{{canopen::CommError::HeartbeatConsumer, 7}}));
}
