// WDGA start-up and NMT: automatic bit-rate detection, boot-up, states, addressing, heartbeat
// producer and consumer, node guarding, error behaviour 1029h:01, NMT start-up 1F80h (digest
// checklist 1, 2, 8-11, 36, 40; vectors N1-N9).
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

class Boot : public WdgaTest {
 protected:
  Boot() : WdgaTest({}, "", false) {}
};

TEST_F(Boot, SilentUntilAFrameRevealsTheBitRate) {
  device().power_on(h().now());
  h().run_ms(5000);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(device().led(), Led::RedGreenFlicker);
  h().send(Frame(0x080, eight({})));
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x00})});
  EXPECT_EQ(device().led(), Led::GreenBlinking);
  // Pre-operational: SDO answers, SYNC gives no PDO.
  EXPECT_EQ(sdo({0x40, 0x04, 0x60, 0x00})->data[0], 0x43);
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  h().run_ms(5);
  EXPECT_TRUE(h().take().empty());
}

TEST_F(Boot, TheDetectingFrameItselfIsNotProcessed) {
  device().power_on(h().now());
  h().run_ticks(1);
  h().send(0x67F, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x00})});  // boot-up, but no SDO answer
}

TEST_F(Boot, AFixedBitRateBootsAtOnceAndAMismatchIsSilent) {
  h().bus().set_bit_rate_kbit(500);
  h().power_on();  // still detecting
  ASSERT_EQ(h().take(), Frames{});
  h().send(Frame(0x080, eight({})));
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x00})});
  EXPECT_EQ(device().node().bit_rate_kbit(), 500u);
  // 2100h = 3 (250 kbit/s), active after a reset: at 500 kbit/s the node is then unreachable.
  ASSERT_EQ(h().write(0x2100, 0, 3, 1), 0u);
  EXPECT_EQ(u(0x2100), 3u);
  h().nmt(0x82, 0x7F);
  h().run_ms(5);
  EXPECT_TRUE(h().take().empty());
  h().bus().set_bit_rate_kbit(250);
  EXPECT_EQ(u(0x2100), 3u);
}

class Nmt : public WdgaTest {
 protected:
  Nmt() : WdgaTest({{"temperature_period_s", "1"}}) {}
};

TEST_F(Nmt, StatesAndAddressing) {
  h().nmt(0x01, 0x7F);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
  h().nmt(0x02, 0x7F);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Stopped);
  EXPECT_EQ(device().led(), Led::GreenSingleFlash);
  h().nmt(0x80, 0x7F);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
  h().nmt(0x02, 0x05);  // another node
  h().nmt(0x02, 0x80);  // invalid node-ID
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
  h().send(Frame(0x000, {0x01, 0x00, 0xAA}));  // DLC 3: processed [R]
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
  h().send(Frame(0x000, {0x80}));  // DLC 1: ignored
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
}

TEST_F(Nmt, StoppedAnswersNoSdoSendsNoPdoOrEmcy) {
  start();
  h().nmt(0x02, 0x7F);
  h().take();
  h().send(0x67F, {0x40, 0x04, 0x60, 0x00, 0, 0, 0, 0});
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  device().inject_fault("over_temperature", true);
  turn_to(0.5);
  h().run_ms(1100);
  EXPECT_TRUE(h().take().empty());
  // The heartbeat (NMT still works in Stopped) carries 04h.
  h().nmt(0x80, 0x7F);
  ASSERT_EQ(h().write(0x1017, 0, 100, 2), 0u);
  h().nmt(0x02, 0x7F);
  h().take();
  h().run_ms(101);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x04})});
}

TEST_F(Nmt, HeartbeatEveryPeriodWithTheState) {
  EXPECT_EQ(sdo({0x2B, 0x17, 0x10, 0x00, 0x88, 0x13}), resp({0x60, 0x17, 0x10, 0x00}));
  h().run_ms(15001);
  const auto times = h().take_times();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[1] - times[0], sim::milliseconds(5000));
  h().run_ms(5000);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x7F})});
  start();
  h().take();
  h().run_ms(5000);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x05})});
  // Node guarding is inactive while the heartbeat runs.
  h().send(Frame::remote(0x77F, 1));
  EXPECT_TRUE(h().take().empty());
}

TEST_F(Nmt, ResetCommunicationForgetsUnsavedCommunicationSettings) {
  ASSERT_EQ(h().write(0x1017, 0, 1000, 2), 0u);
  h().nmt(0x82, 0x7F);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x00})});
  EXPECT_EQ(u(0x1017), 0u);
  h().run_ms(3000);
  EXPECT_TRUE(h().take().empty());
}

TEST_F(Nmt, ResetNodeForgetsUnsavedApplicationSettings) {
  ASSERT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
  h().nmt(0x81, 0x7F);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x00})});
  EXPECT_EQ(u(0x6001), 16384u);
}

TEST_F(Nmt, NodeGuardingTogglesWhenNoHeartbeat) {
  h().send(Frame::remote(0x77F, 1));
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x7F})});
  h().send(Frame::remote(0x77F, 1));
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0xFF})});
}

TEST_F(Nmt, LifeGuardingTimeoutSends8130) {
  ASSERT_EQ(h().write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(h().write(0x100D, 0, 2, 1), 0u);
  start();
  h().send(Frame::remote(0x77F, 1));
  h().take();
  h().run_ms(210);
  EXPECT_EQ(h().take(), Frames{emcy({0x30, 0x81, 0x10})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
  EXPECT_EQ(u(0x2502, 1), 0x8130u);
}

class HeartbeatConsumer : public WdgaTest {
 protected:
  /// Consumer for node 127's heartbeat, 1000 ms, written as the manual's example byte layout.
  void watch() {
    EXPECT_EQ(sdo({0x23, 0x16, 0x10, 0x01, 0xE8, 0x03, 0x7E, 0x00}), resp({0x60, 0x16, 0x10, 0x01}));
  }
};

TEST_F(HeartbeatConsumer, TimeoutSends8130AndGoesPreOperational) {  // checklist 36
  watch();
  ASSERT_EQ(h().write(0x1017, 0, 250, 2), 0u);  // its own heartbeat shows the fallback
  start();
  h().send(Frame(0x77E, {0x05}));
  h().run_ms(900);
  h().send(Frame(0x77E, {0x05}));
  h().take();
  h().run_ms(1002);
  // The EMCY once; heartbeats before it say Operational (05), any after it Pre-operational (7F).
  Frames emcys;
  for (const auto& f : h().take()) {
    if (f.id == 0x77F) {
      EXPECT_EQ(f, Frame(0x77F, {emcys.empty() ? std::uint8_t{0x05} : std::uint8_t{0x7F}}));
    } else {
      emcys.push_back(f);
    }
  }
  EXPECT_EQ(emcys, Frames{emcy({0x30, 0x81, 0x10})});
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
  h().run_ms(250);
  EXPECT_EQ(h().take(), Frames{Frame(0x77F, {0x7F})});  // one period: exactly one heartbeat
  h().send(Frame(0x77E, {0x05}));  // back: error reset
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{emcy({0x00, 0x00, 0x00})});
}

TEST_F(HeartbeatConsumer, ErrorBehaviourStoppedOrUnchanged) {
  EXPECT_EQ(h().write(0x1029, 1, 3, 1), 0x06090030u);
  ASSERT_EQ(h().write(0x1029, 1, 2, 1), 0u);
  watch();
  start();
  h().send(Frame(0x77E, {0x05}));
  h().run_ms(1002);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Stopped);
  h().nmt(0x01, 0x7F);
  ASSERT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
  ASSERT_EQ(h().write(0x1029, 1, 1, 1), 0u);
  h().send(Frame(0x77E, {0x05}));
  h().run_ms(1002);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
}

class Startup : public WdgaTest {
 protected:
  void save_startup(std::uint32_t v) {
    ASSERT_EQ(h().write(0x1F80, 0, v, 4), 0u);
    ASSERT_EQ(h().write(0x1010, 2, kSave, 4), 0u);
  }
};

TEST_F(Startup, AutostartOperational) {
  EXPECT_EQ(h().write(0x1F80, 0, 0x04, 4), 0x06090030u);
  save_startup(0x08);
  device().power_off();
  h().run_ms(10);
  device().power_on(h().now());
  h().run_ticks(1);
  h().send(Frame(0x080, eight({})));
  h().run_ticks(1);
  const auto got = h().take();
  ASSERT_GE(got.size(), 2u);
  EXPECT_EQ(got[0], Frame(0x77F, {0x00}));
  EXPECT_EQ(got[1].id, 0x1FFu);  // TPDO1 without any NMT command
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
}

TEST_F(Startup, StartAllNodesAsMiniMaster) {
  save_startup(0x02);
  device().power_off();
  device().power_on(h().now());
  h().run_ticks(1);
  h().send(Frame(0x080, eight({})));
  h().run_ticks(1);
  const auto got = h().take();
  ASSERT_GE(got.size(), 2u);
  EXPECT_EQ(got[0], Frame(0x77F, {0x00}));
  EXPECT_EQ(got[1], Frame(0x000, {0x01, 0x00}));
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
}

}  // namespace
}  // namespace wdga::test
