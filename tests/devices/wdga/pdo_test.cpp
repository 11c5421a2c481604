// WDGA transmit PDOs with the vendor's transmission-type table (Tab. 8.46), variable mapping and
// the Pre-operational-only parameter rule (digest checklist 6, 7, 17-22; vectors W4-W10, §5.5).
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

class Pdo : public WdgaTest {
 protected:
  Pdo() { turn_to(0x12345 / 16384.0 + 0.5 / 16384); h().run_ms(2); }
  const Frame kPosition{0x1FF, {0x45, 0x23, 0x01, 0x00}};
};

TEST_F(Pdo, ChangeDrivenTpdo1AfterStart) {
  start();
  EXPECT_EQ(h().take(), Frames{kPosition});  // once on entering Operational [R]
  h().run_ms(100);
  EXPECT_TRUE(h().take().empty());  // shaft still
  turn_to(0x12346 / 16384.0 + 0.5 / 16384);
  h().run_ms(2);
  EXPECT_EQ(h().take(), Frames{Frame(0x1FF, {0x46, 0x23, 0x01, 0x00})});
  h().send(Frame::remote(0x1FF, 4));  // RTR is not supported
  EXPECT_TRUE(h().take().empty());
}

TEST_F(Pdo, SyncGivesTpdo2AndTpdo3) {
  start();
  h().take();
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  EXPECT_EQ(h().take(), (Frames{Frame(0x2FF, {0x45, 0x23, 0x01, 0x00}),
                                Frame(0x3FF, {0x45, 0x23, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00})}));
  h().send(Frame(0x080, eight({})));  // any DLC
  EXPECT_EQ(h().take().size(), 2u);
}

TEST_F(Pdo, SynchronousEveryNthSync) {
  EXPECT_EQ(sdo({0x2F, 0x00, 0x18, 0x02, 0x01}), resp({0x60, 0x00, 0x18, 0x02}));
  start();
  EXPECT_TRUE(h().take().empty());  // no initial frame for a synchronous PDO
  turn_to(0.7);
  h().run_ms(5);
  EXPECT_TRUE(h().take().empty());  // and no change-driven one
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  EXPECT_EQ(h().take().size(), 3u);  // TPDO1, 2, 3
  h().nmt(0x80, 0x7F);
  ASSERT_EQ(h().write(0x1800, 2, 5, 1), 0u);
  start();
  int tpdo1 = 0;
  for (int i = 0; i < 10; ++i) {
    h().send(Frame(0x080, std::vector<std::uint8_t>{}));
    for (const auto& f : h().take()) tpdo1 += f.id == 0x1FF;
  }
  EXPECT_EQ(tpdo1, 2);
}

TEST_F(Pdo, CyclicOnTheEventTimer) {
  ASSERT_EQ(sdo({0x2F, 0x00, 0x18, 0x02, 0xFF}), resp({0x60, 0x00, 0x18, 0x02}));
  ASSERT_EQ(sdo({0x2B, 0x00, 0x18, 0x05, 0x1E, 0x00}), resp({0x60, 0x00, 0x18, 0x05}));
  start();
  h().take();
  h().run_ms(301);
  std::vector<sim::Time> t;
  for (auto& x : h().take_times()) t.push_back(x);
  ASSERT_EQ(t.size(), 10u);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_EQ(t[i] - t[i - 1], sim::milliseconds(30));
}

TEST_F(Pdo, OffByTypeFFWithoutTimerOrByTheCobId) {
  ASSERT_EQ(h().write(0x1800, 2, 0xFF, 1), 0u);
  start();
  turn_to(0.9);
  h().run_ms(20);
  for (const auto& f : h().take()) EXPECT_NE(f.id, 0x1FFu);
  h().nmt(0x80, 0x7F);
  ASSERT_EQ(h().write(0x1800, 2, 0xFE, 1), 0u);
  EXPECT_EQ(sdo({0x23, 0x00, 0x18, 0x01, 0xFF, 0x01, 0x00, 0xC0}), resp({0x60, 0x00, 0x18, 0x01}));
  start();
  turn_to(0.1);
  h().run_ms(20);
  for (const auto& f : h().take()) EXPECT_NE(f.id, 0x1FFu);
}

TEST_F(Pdo, ParametersOnlyInPreOperational) {
  start();
  EXPECT_EQ(sdo({0x2F, 0x00, 0x18, 0x02, 0x01}), resp({0x80, 0x00, 0x18, 0x02, 0x22, 0x00, 0x00, 0x08}));
  EXPECT_EQ(h().write(0x1800, 5, 10, 2), 0x08000022u);
  EXPECT_EQ(h().write(0x1A00, 0, 0, 1), 0x08000022u);
  EXPECT_EQ(h().write(0x1800, 1, 0xC00001FF, 4), 0u);  // the COB-ID in any state
  h().nmt(0x80, 0x7F);
  EXPECT_EQ(h().write(0x1800, 2, 0xF1, 1), 0x06090030u);
  EXPECT_EQ(h().write(0x1800, 2, 0xFD, 1), 0x06090030u);
  EXPECT_EQ(h().write(0x1800, 2, 0xF0, 1), 0u);
}

TEST_F(Pdo, VariableMappingFromTheManual) {
  ASSERT_EQ(h().write(0x6001, 0, 16384, 4), 0u);
  EXPECT_EQ(sdo({0x2F, 0x00, 0x1A, 0x00, 0x00}), resp({0x60, 0x00, 0x1A, 0x00}));
  EXPECT_EQ(sdo({0x23, 0x00, 0x1A, 0x01, 0x20, 0x00, 0x04, 0x60}), resp({0x60, 0x00, 0x1A, 0x01}));
  EXPECT_EQ(sdo({0x23, 0x00, 0x1A, 0x02, 0x10, 0x01, 0x30, 0x60}), resp({0x60, 0x00, 0x1A, 0x02}));
  EXPECT_EQ(sdo({0x23, 0x00, 0x1A, 0x03, 0x10, 0x01, 0x40, 0x60}), resp({0x60, 0x00, 0x1A, 0x03}));
  EXPECT_EQ(sdo({0x2F, 0x00, 0x1A, 0x00, 0x03}), resp({0x60, 0x00, 0x1A, 0x00}));
  // 60 rpm clockwise for 2 s: speed = 16384 steps/s, acceleration back to 0.
  const double start_rev = 0.0;
  turn_to(start_rev);
  h().run_ms(2);
  start();
  h().take();
  for (int ms = 0; ms < 2000; ++ms) {
    turn_to(start_rev + ms / 1000.0);
    h().run_ticks(1);
  }
  const auto frames = h().take();
  ASSERT_FALSE(frames.empty());
  const auto& last = frames.back();
  ASSERT_EQ(last.id, 0x1FFu);
  ASSERT_EQ(last.data.size(), 8u);
  const auto speed = static_cast<std::int16_t>(last.data[4] | last.data[5] << 8);
  const auto accel = static_cast<std::int16_t>(last.data[6] | last.data[7] << 8);
  EXPECT_NEAR(speed, 16384, 20);
  EXPECT_NEAR(accel, 0, 20);
  const std::uint32_t pos = last.data[0] | last.data[1] << 8 | last.data[2] << 16 | static_cast<std::uint32_t>(last.data[3]) << 24;
  EXPECT_EQ(pos, static_cast<std::uint32_t>(std::floor(1.999 * 16384)));
}

TEST_F(Pdo, MappingErrors) {
  EXPECT_EQ(sdo({0x23, 0x00, 0x1A, 0x01, 0x20, 0x00, 0x04, 0x60}), resp({0x80, 0x00, 0x1A, 0x01, 0x22, 0x00, 0x00, 0x08}));
  ASSERT_EQ(h().write(0x1A00, 0, 0, 1), 0u);
  ASSERT_EQ(h().write(0x1A00, 1, 0x60040020, 4), 0u);
  ASSERT_EQ(h().write(0x1A00, 2, 0x60080040, 4), 0u);
  ASSERT_EQ(h().write(0x1A00, 3, 0x60300110, 4), 0u);
  EXPECT_EQ(h().write(0x1A00, 0, 3, 1), 0x06040042u);  // 112 bits
  EXPECT_EQ(h().write(0x1A00, 1, 0x60000010, 4), 0x06040041u);  // 6000h is not mappable
  EXPECT_EQ(h().write(0x1A00, 1, 0x60040010, 4), 0x06040041u);  // wrong length
  EXPECT_EQ(h().write(0x1A00, 0, 9, 1), 0x06090031u);
  ASSERT_EQ(h().write(0x1A00, 1, 0x63000108, 4), 0u);  // CAM state, work area, alarms, ...
  ASSERT_EQ(h().write(0x1A00, 2, 0x64000108, 4), 0u);
  ASSERT_EQ(h().write(0x1A00, 3, 0x65030010, 4), 0u);
  ASSERT_EQ(h().write(0x1A00, 4, 0x25000110, 4), 0u);
  EXPECT_EQ(h().write(0x1A00, 0, 4, 1), 0u);
  EXPECT_EQ(h().write(0x1A00, 5, 0x25000210, 4), 0x08000022u);  // sub 0 is not 0 any more
}

TEST_F(Pdo, TypeZeroSendsOnSyncOnlyAfterAChange) {
  ASSERT_EQ(h().write(0x1800, 2, 0x00, 1), 0u);
  start();
  h().take();
  auto tpdo1_on_sync = [&] {
    h().send(Frame(0x080, std::vector<std::uint8_t>{}));
    int n = 0;
    for (const auto& f : h().take()) n += f.id == 0x1FF;
    return n;
  };
  EXPECT_EQ(tpdo1_on_sync(), 1);  // never sent yet
  EXPECT_EQ(tpdo1_on_sync(), 0);
  turn_to(0.3);
  h().run_ms(2);
  EXPECT_EQ(tpdo1_on_sync(), 1);
}

TEST_F(Pdo, CyclicTimerPacesChangeDrivenTpdo1) {
  ASSERT_EQ(h().write(0x6200, 0, 10, 2), 0u);
  start();
  h().take();
  for (int ms = 0; ms < 100; ++ms) {
    turn_to(ms / 1000.0);  // the value changes every millisecond
    h().run_ticks(1);
  }
  const auto times = h().take_times();
  ASSERT_GE(times.size(), 9u);
  ASSERT_LE(times.size(), 11u);
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_GE(times[i] - times[i - 1], sim::milliseconds(10));
}

class LiteralTpdo3 : public WdgaTest {
 protected:
  LiteralTpdo3() : WdgaTest({{"tpdo3_literal_mapping", "on"}, {"cobid_no_rtr_bit", "off"}}) {}
};

TEST_F(LiteralTpdo3, PrintedMappingSendsFourBytes) {
  EXPECT_EQ(u(0x1A02, 1), 0x60080020u);
  EXPECT_EQ(u(0x1802, 1), 0x3FFu);
  turn_to(3.0);
  h().run_ms(2);
  start();
  h().take();
  h().send(Frame(0x080, std::vector<std::uint8_t>{}));
  const auto frames = h().take();
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1], Frame(0x3FF, {0x00, 0xC0, 0x00, 0x00}));
}

class NoInitialTpdo : public WdgaTest {
 protected:
  NoInitialTpdo() : WdgaTest({{"initial_tpdo", "off"}}) {}
};

TEST_F(NoInitialTpdo, StartSendsNothingWhileTheShaftStands) {
  start();
  h().run_ms(50);
  EXPECT_TRUE(h().take().empty());
}

}  // namespace
}  // namespace wdga::test
