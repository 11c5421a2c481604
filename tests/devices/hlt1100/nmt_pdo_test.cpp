// HLT 1100 NMT, guarding and the two fixed TPDOs (digest checklist 1, 2, 13-19, 31, 39; test
// vectors 1-6, 32-34). Magnet at 100.0 mm = 1000 steps = E8 03 00 00.
#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

const Frame kTpdo1{0x185, {0xE8, 0x03, 0x00, 0x00}};
const Frame kTpdo2{0x285, {0xE8, 0x03, 0x00, 0x00}};

class NmtPdo : public Hlt1100Test {
 protected:
  NmtPdo() : Hlt1100Test({}, 5, false) {}
  void boot() {
    h().power_on();
    h().take();
  }
  Frame guard(std::uint8_t state) { return Frame(0x705, {state}); }
  Frames guard_rtr() {
    h().send(Frame::remote(0x705, 1));
    return h().take();
  }
};

TEST_F(NmtPdo, BootUpIsTheOnlyFrameThenGuardingAnswersWithToggle) {
  h().power_on();
  h().run_ms(500);
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(guard_rtr(), Frames{guard(0x7F)});
  EXPECT_EQ(guard_rtr(), Frames{guard(0xFF)});
  EXPECT_EQ(guard_rtr(), Frames{guard(0x7F)});
}

TEST_F(NmtPdo, SyncInPreOperationalGivesNothingStartSendsTpdo1Once) {
  boot();
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(start(), Frames{kTpdo1});
  h().run_ms(1000);
  EXPECT_TRUE(h().take().empty());  // 6200h = 0: no more
  EXPECT_TRUE(start().empty());     // already Operational: no second one-shot
  h().nmt(0x80, 5);
  EXPECT_EQ(start(), Frames{kTpdo1});  // every entry into Operational
}

TEST_F(NmtPdo, GuardingInOperationalToggles85_05_85) {
  boot();
  start();
  EXPECT_EQ(guard_rtr(), Frames{guard(0x05)});  // toggle starts at 0 after boot-up
  EXPECT_EQ(guard_rtr(), Frames{guard(0x85)});
  EXPECT_EQ(guard_rtr(), Frames{guard(0x05)});
}

TEST_F(NmtPdo, SyncWithDlc0TriggersTpdo2DlcOneIsIgnored) {
  boot();
  start();
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  EXPECT_EQ(h().take(), Frames{kTpdo2});
  h().send(Frame(0x080, {0x01}));
  EXPECT_TRUE(h().take().empty());
  magnet_mm(100.1);
  h().run_ticks(1);
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  EXPECT_EQ(h().take(), Frames{Frame(0x285, {0xE9, 0x03, 0x00, 0x00})});
}

TEST_F(NmtPdo, RemoteRequestOnTpdo2OnlyInOperational) {
  boot();
  h().send(Frame::remote(0x285, 4));
  EXPECT_TRUE(h().take().empty());
  start();
  h().send(Frame::remote(0x285, 4));
  EXPECT_EQ(h().take(), Frames{kTpdo2});
}

TEST_F(NmtPdo, CyclicTimerIsTheEventTimerOfTpdo1) {
  boot();
  start();
  ASSERT_EQ(h().write(0x6200, 0, 100, 2), 0u);
  EXPECT_EQ(sdo({0x40, 0x00, 0x18, 0x05}), Frame(0x585, eight({0x4B, 0x00, 0x18, 0x05, 0x64})));
  h().take();
  h().run_ms(1001);  // the timer restarts at the write: frames at +100 ... +1000 ms
  const auto times = h().take_times();
  ASSERT_EQ(times.size(), 10u);
  for (std::size_t i = 1; i < times.size(); ++i) {
    EXPECT_NEAR(sim::seconds(times[i] - times[i - 1]), 0.100, 0.002);
  }
  ASSERT_EQ(h().write(0x1800, 5, 0, 2), 0u);
  EXPECT_EQ(h().read_u(0x6200, 0), 0u);
  h().take();
  h().run_ms(500);
  EXPECT_TRUE(h().take().empty());
}

TEST_F(NmtPdo, InhibitTimeSpacesTpdo1) {
  boot();
  ASSERT_EQ(h().write(0x1800, 3, 100, 2), 0u);  // 10 ms
  ASSERT_EQ(h().write(0x6200, 0, 5, 2), 0u);
  start();
  h().take();
  h().run_ms(200);
  const auto times = h().take_times();
  ASSERT_GE(times.size(), 15u);
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_GE(times[i] - times[i - 1], sim::milliseconds(10));
}

TEST_F(NmtPdo, StoppedSilencesPdoSdoAndEmcyButNotGuarding) {
  boot();
  ASSERT_EQ(h().write(0x6200, 0, 10, 2), 0u);
  start();
  h().nmt(0x02, 0);
  h().run_ms(50);
  EXPECT_TRUE(h().take().empty());
  h().send(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(guard_rtr(), Frames{guard(0x04)});
  EXPECT_EQ(guard_rtr(), Frames{guard(0x84)});
  device().inject_fault("magnet_lost", true);
  h().run_ms(10);
  EXPECT_TRUE(h().take().empty());  // no EMCY in Stopped
  h().nmt(0x80, 5);
  EXPECT_EQ(h().read_u(0x6503, 0), 1u);
}

TEST_F(NmtPdo, ForeignNodeIdAndWrongDlcAreIgnored) {
  boot();
  h().nmt(0x01, 6);
  h().send(Frame(0x000, {0x01, 0x05, 0x00}));
  h().send(Frame(0x000, {0x01}));
  h().run_ms(5);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(NmtPdo, ResetCommunicationSendsBootUpAndClearsTheErrorList) {
  boot();
  device().inject_fault("can_error", true);
  EXPECT_EQ(h().read_u(0x1003, 0), 1u);
  h().take();
  h().nmt(0x82, 5);
  h().run_ticks(1);
  EXPECT_EQ(h().take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h().read_u(0x1003, 0), 0u);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(NmtPdo, LifeGuardingTimeoutReturnsToPreOperationalWithoutEmcy) {  // checklist 31
  boot();
  ASSERT_EQ(h().write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(h().write(0x100D, 0, 3, 1), 0u);
  ASSERT_EQ(h().write(0x6200, 0, 40, 2), 0u);  // cyclic TPDO1, so that "TPDOs stop" is visible
  EXPECT_EQ(start(), Frames{kTpdo1});
  EXPECT_EQ(guard_rtr(), Frames{guard(0x05)});
  h().run_ms(290);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
  EXPECT_EQ(h().take(), Frames(7, kTpdo1));  // every 40 ms up to 280 ms
  h().run_ms(20);
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::PreOperational);
  EXPECT_TRUE(h().take().empty());  // the timeout at 300 ms, before the 320 ms TPDO
  // After the timeout nothing: no EMCY by default, no cyclic TPDO1, no TPDO2 on SYNC.
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  h().run_ms(500);
  EXPECT_TRUE(h().take().empty());
  EXPECT_EQ(guard_rtr(), Frames{guard(0xFF)});
}

TEST_F(NmtPdo, NmtStartupAutostartAfterSaveAndPowerCycle) {
  boot();
  EXPECT_EQ(h().write(0x1F80, 0, 0x04, 4), 0x06090030u);
  ASSERT_EQ(h().write(0x1F80, 0, 0x08, 4), 0u);
  h().take();
  h().send(0x605, {0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65});
  h().run_ms(3100);
  h().take();
  power_cycle();
  EXPECT_EQ(h().take(), (Frames{Frame(0x705, {0x00}), kTpdo1}));
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
}

class LifeGuardEmcy : public Hlt1100Test {
 protected:
  LifeGuardEmcy() : Hlt1100Test({{"life_guard_emcy", "0x8130"}}) {}
};

TEST_F(LifeGuardEmcy, KnobSendsAnEmcyOnTheTimeout) {
  ASSERT_EQ(h().write(0x100C, 0, 10, 2), 0u);
  ASSERT_EQ(h().write(0x100D, 0, 2, 1), 0u);
  h().send(Frame::remote(0x705, 1));
  h().take();
  h().run_ms(30);
  EXPECT_EQ(h().take(), Frames{emcy({0x30, 0x81, 0x11})});
}

class ProseStartup : public Hlt1100Test {
 protected:
  ProseStartup() : Hlt1100Test({{"nmt_startup_bit2", "prose"}}) {}
};

TEST_F(ProseStartup, Bit2SetMeansAutostart) {
  EXPECT_EQ(h().read_u(0x1F80, 0), 0x08u);  // no autostart by default in both readings
  ASSERT_EQ(h().write(0x1F80, 0, 0x0C, 4), 0u);
  h().write(0x1010, 1, kSave, 4);
  h().run_ms(3100);
  power_cycle();
  EXPECT_EQ(device().node().nmt_state(), canopen::NmtState::Operational);
}

}  // namespace
}  // namespace hlt1100::test
