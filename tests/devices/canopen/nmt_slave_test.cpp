// NMT slave and boot-up, frame level (node 5).
#include "devices/canopen/nmt_slave.h"

#include <gtest/gtest.h>

#include "devices/transition_log.h"
#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;
using canopen::NmtState;

namespace {
struct Recorder : canopen::Application {
  std::vector<std::string> events;
  void on_reset_application() override { events.push_back("app"); }
  void on_reset_communication() override { events.push_back("comm"); }
  void on_nmt_state_changed(NmtState, NmtState to) override { events.push_back("state " + std::string(canopen::to_string(to))); }
};
}  // namespace

TEST(NmtSlave, BootUpFrameAndPreOperational) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h.node().nmt_state(), NmtState::PreOperational);
}

TEST(NmtSlave, BootDelayIsHonoured) {
  canopen::NodePolicy p;
  p.nmt.boot_delay = sim::milliseconds(300);
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  EXPECT_TRUE(h.take().empty());
  h.run_ms(298);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
}

TEST(NmtSlave, AddressedAndBroadcastCommandsChangeState) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.nmt(0x01, 5);
  EXPECT_EQ(h.node().nmt_state(), NmtState::Operational);
  h.nmt(0x80, 6);  // another node: ignored
  EXPECT_EQ(h.node().nmt_state(), NmtState::Operational);
  h.nmt(0x02, 0);  // broadcast
  EXPECT_EQ(h.node().nmt_state(), NmtState::Stopped);
  h.nmt(0x80, 0);
  EXPECT_EQ(h.node().nmt_state(), NmtState::PreOperational);
  h.nmt(0x7E, 5);  // unknown command: ignored
  EXPECT_EQ(h.node().nmt_state(), NmtState::PreOperational);
  h.send(0x000, {0x01});  // DLC 1: ignored
  h.send(0x000, {0x01, 0x05, 0x00});  // DLC 3: ignored (CiA 301 requires DLC 2)
  EXPECT_EQ(h.node().nmt_state(), NmtState::PreOperational);
}

TEST(NmtSlave, ResetNodeAndResetCommunicationBootAgain) {
  Recorder app;
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5, &app);
  h.power_on();
  h.take();
  ASSERT_EQ(h.write(0x2000, 0, 99, 1), 0u);   // application area
  ASSERT_EQ(h.write(0x1017, 0, 1000, 2), 0u);  // communication area
  h.nmt(0x01, 5);
  app.events.clear();
  h.nmt(0x82, 5);  // reset communication: comm area back to defaults, application kept
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h.node().nmt_state(), NmtState::PreOperational);
  EXPECT_EQ(h.node().od().get<int>(0x1017), 0);
  EXPECT_EQ(h.node().od().get<int>(0x2000), 99);
  EXPECT_EQ(app.events, (std::vector<std::string>{"comm", "state PRE-OPERATIONAL"}));
  app.events.clear();
  h.nmt(0x81, 0);  // reset node: both areas
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h.node().od().get<int>(0x2000), 7);
  EXPECT_EQ(app.events, (std::vector<std::string>{"app", "comm", "state PRE-OPERATIONAL"}));
}

TEST(NmtSlave, ServicesFollowTheState) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.take();
  // Pre-operational: SDO yes, PDO no.
  h.send(0x205, {1, 0, 0, 0, 0x22, 0x11});
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), 0);
  EXPECT_TRUE(h.read(0x1000, 0).has_value());
  // Operational: RPDO accepted.
  h.nmt(0x01, 5);
  h.take();
  h.send(0x205, {1, 0, 0, 0, 0x22, 0x11});
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), 1);
  // Stopped: neither SDO nor PDO; NMT and guarding still work.
  h.nmt(0x02, 5);
  h.take();
  h.send(0x205, {2, 0, 0, 0, 0, 0});
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), 1);
  EXPECT_FALSE(h.read(0x1000, 0).has_value());
  h.send(Frame::remote(0x705, 1));
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x04})});
}

// The NMT machine's transition log: each change with its command, the sender and the boot-up
// that a reset starts (CiA 301 names; OFF for power).
TEST(NmtSlave, TransitionsAreRecordedWithTheirCause) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  devices::TransitionLog log;
  h.node().set_transition_log(&log);
  h.power_on();
  h.nmt(0x01, 5);
  h.nmt(0x02, 0);
  h.nmt(0x82, 5);
  h.run_ms(10);
  std::vector<devices::Transition> t;
  log.for_each_after(0, [&](const devices::Transition& e) { t.push_back(e); });
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[0].from, "OFF");
  EXPECT_EQ(t[0].to, "INITIALISING");
  EXPECT_EQ(t[0].cause, devices::TransitionCause::Boot);
  EXPECT_EQ(t[1].transition, "boot-up");
  EXPECT_EQ(t[1].to, "PRE-OPERATIONAL");
  EXPECT_EQ(t[2].transition, "NMT 01h");
  EXPECT_EQ(t[2].to, "OPERATIONAL");
  EXPECT_EQ(t[2].cause, devices::TransitionCause::NmtCommand);
  EXPECT_EQ(t[2].value, 0x01u);
  EXPECT_EQ(t[2].detail, "the master");
  EXPECT_EQ(t[3].transition, "NMT 02h");
  EXPECT_EQ(t[3].to, "STOPPED");
  EXPECT_EQ(t[4].transition, "NMT 82h");
  EXPECT_EQ(t[4].from, "STOPPED");
  EXPECT_EQ(t[4].to, "INITIALISING");
  EXPECT_EQ(t[5].transition, "boot-up");
  EXPECT_EQ(t[5].cause, devices::TransitionCause::NmtCommand);  // the boot-up the reset started
  EXPECT_EQ(t[5].value, 0x82u);
  for (const auto& e : t) EXPECT_EQ(e.machine, "nmt");

  h.node().power_off();
  std::vector<devices::Transition> off;
  log.for_each_after(6, [&](const devices::Transition& e) { off.push_back(e); });
  ASSERT_EQ(off.size(), 1u);
  EXPECT_EQ(off[0].to, "OFF");
  EXPECT_EQ(off[0].cause, devices::TransitionCause::Power);
}

TEST(NmtSlave, WiredFromAboveHandsAddressedCommandsOn) {
  vtest::FakeNodeLinks links;
  links.status.node_id = 5;
  canopen::NmtPolicy policy;
  canopen::NmtSlave nmt(policy, links.status, links);
  nmt.on_frame(Frame(0x000, {0x01, 5}).to_can());
  nmt.on_frame(Frame(0x000, {0x80, 6}).to_can());  // another node
  nmt.on_frame(Frame(0x000, {0x82, 0}).to_can());  // broadcast
  EXPECT_EQ(links.nmt_commands,
            (std::vector<canopen::NmtCommand>{canopen::NmtCommand::Start, canopen::NmtCommand::ResetCommunication}));
}
