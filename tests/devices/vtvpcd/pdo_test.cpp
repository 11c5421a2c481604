// PDOs as the manual configures and starts them (§3.4): the Bus Manager example mapping,
// event-timer transmission started by NMT, RPDOs in Operational only (digest §2.9; checklist
// 18-24, 40; TV9, TV30, TV37-TV39), and the DS-301 mapping objects (A16).
#include <gtest/gtest.h>

#include "devices/canopen/pdo_service.h"
#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using vtest::Frame;
using vtest::Frames;
using Bytes = std::vector<std::uint8_t>;

namespace {
/// Runs `ms` one-millisecond ticks one at a time; every frame the master got, stamped with the
/// time of the tick that sent it (as the harness's own take_times() would, without losing the frames).
struct Timed {
  Frames frames;
  std::vector<sim::Time> times;
};
Timed run_collecting(vtest::Vtvpcd& n, int ms) {
  Timed out;
  for (int i = 0; i < ms; ++i) {
    const auto tick = n->now();
    n->run_ms(1);
    for (auto& f : n->take()) {
      out.frames.push_back(std::move(f));
      out.times.push_back(tick);
    }
  }
  return out;
}
}  // namespace

TEST(VtvpcdPdo, NoTransmissionBeforeNmtStart) {  // checklist 18
  vtest::Vtvpcd n;
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n->run_ms(1500);
  EXPECT_TRUE(n->take().empty());
}

TEST(VtvpcdPdo, ExampleTpdo1EveryEventTimerPeriodAfterStart) {  // checklist 19, TV9
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  n.set("pressure_b", 150e5);
  n.set("swivel_angle", 0.5);
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n->send(0x000, {0x01, 0x3F});
  n->run_ms(350);
  const auto frames = n->take();
  ASSERT_EQ(frames.size(), 3u);
  for (const auto& f : frames) EXPECT_EQ(f, Frame(0x1BF, {0xFF, 0xBF, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00}));
  vtest::Vtvpcd m({{"builtin_plant", "false"}});
  ASSERT_EQ(m->write(0x1800, 5, 100, 2), 0u);
  m->send(0x000, {0x01, 0x3F});
  const auto t0 = m->now();
  m->run_ms(350);
  const auto times = m->take_times();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ((times[0] - t0).count(), 100000);
  EXPECT_EQ((times[1] - times[0]).count(), 100000);
  EXPECT_EQ((times[2] - times[1]).count(), 100000);
}

TEST(VtvpcdPdo, ManualSequenceOnNode5) {  // checklist 8, TV6-TV9
  vtest::Vtvpcd n({{"builtin_plant", "false"}}, 5);
  n.set("pressure_b", 150e5);
  n.set("swivel_angle", 0.5);
  n->send(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00});  // TV6
  EXPECT_EQ(n->take(), Frames{Frame(0x585, {0x60, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00})});
  n->send(0x605, {0x42, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00});  // TV7
  EXPECT_EQ(n->take(), Frames{Frame(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00})});
  n->send(0x000, {0x01, 0x05});  // TV8
  EXPECT_EQ(n.device->node().nmt_state(), canopen::NmtState::Operational);
  const auto t0 = n->now();
  const auto got = run_collecting(n, 350);
  // TV9: 0x185 every 100 ms with act. pressure B 150 bar and Discrete Outputs OK + DO1.
  const Frame tv9(0x185, {0xFF, 0xBF, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00});
  EXPECT_EQ(got.frames, (Frames{tv9, tv9, tv9}));
  ASSERT_EQ(got.times.size(), 3u);
  for (std::size_t i = 0; i < got.times.size(); ++i) EXPECT_EQ(got.times[i] - t0, sim::milliseconds(100 * (i + 1))) << i;
}

TEST(VtvpcdPdo, SecondTpdoAndStoppingByTimerZero) {  // checklist 20
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  n.set("pilot_spool_position", -0.25);
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n.start();
  n->run_ms(5);
  n->take();
  ASSERT_EQ(n->write(0x1801, 5, 20, 2), 0u);  // in Operational: the timer starts with the write
  const auto t0 = n->now();
  const auto got = run_collecting(n, 101);
  Frames tpdo1, tpdo2;
  std::vector<sim::Time> t2;
  for (std::size_t i = 0; i < got.frames.size(); ++i) {
    if (got.frames[i].id == 0x2BF) {
      tpdo2.push_back(got.frames[i]);
      t2.push_back(got.times[i]);
    } else {
      tpdo1.push_back(got.frames[i]);
    }
  }
  // act. valve -25 % = -8192.5 -> -8193 (0xFFFFDFFF), DLC 4, every 20 ms from the write.
  ASSERT_EQ(tpdo2.size(), 5u);
  for (std::size_t i = 0; i < tpdo2.size(); ++i) {
    EXPECT_EQ(tpdo2[i], Frame(0x2BF, {0xFF, 0xDF, 0xFF, 0xFF})) << i;
    EXPECT_EQ(t2[i] - t0, sim::milliseconds(20 * (i + 1))) << i;
  }
  for (const auto& f : tpdo1) EXPECT_EQ(f.id, 0x1BFu);
  EXPECT_EQ(tpdo1.size(), 1u);  // TPDO1 went on with its own 100 ms
  // 0x1800:05 = 0 stops 0x1BF at once; 0x2BF goes on.
  ASSERT_EQ(n->write(0x1800, 5, 0, 2), 0u);
  n->run_ms(300);
  const auto after = n->take();
  EXPECT_EQ(after.size(), 15u);
  for (const auto& f : after) EXPECT_EQ(f.id, 0x2BFu);
}

TEST(VtvpcdPdo, Tv30SecondTpdoEvery20MsOnNode5) {  // TV30: timer set, then Operational
  vtest::Vtvpcd n({{"builtin_plant", "false"}}, 5);
  n.set("pilot_spool_position", -0.25);
  ASSERT_EQ(n->write(0x1801, 5, 20, 2), 0u);
  n->run_ms(100);
  EXPECT_TRUE(n->take().empty());  // nothing before the start
  n->send(0x000, {0x01, 0x05});
  const auto t0 = n->now();
  const auto got = run_collecting(n, 101);
  ASSERT_EQ(got.frames.size(), 5u);
  for (std::size_t i = 0; i < got.frames.size(); ++i) {
    EXPECT_EQ(got.frames[i], Frame(0x285, {0xFF, 0xDF, 0xFF, 0xFF})) << i;  // act. valve, DLC 4
    EXPECT_EQ(got.times[i] - t0, sim::milliseconds(20 * (i + 1))) << i;
  }
}

TEST(VtvpcdPdo, RpdoIgnoredInPreOperational) {  // checklist 21
  vtest::Vtvpcd n;
  n->send(0x23F, {0x08, 0x00, 0x00, 0x00, 0x98, 0x99, 0x00, 0x00});
  EXPECT_TRUE(n->take().empty());
  // Checked by SDO: Trigger 0, Pressure CMD (BUS) still its start-up value 114685 (0x0001BFFD).
  EXPECT_EQ(n.sdo({0x40, 0x67, 0x2C, 0x00}), (Bytes{0x43, 0x67, 0x2C, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(n.sdo({0x40, 0x74, 0x2C, 0x00}), (Bytes{0x43, 0x74, 0x2C, 0x00, 0xFD, 0xBF, 0x01, 0x00}));
}

TEST(VtvpcdPdo, ExampleRpdosInOperational) {  // checklist 22, TV38, TV39
  vtest::Vtvpcd n({}, 5);
  n->send(0x000, {0x01, 0x05});
  n->send(0x205, {0x08, 0x00, 0x00, 0x00, 0x98, 0x99, 0x00, 0x00});
  n->send(0x305, {0xFF, 0x5F, 0x00, 0x00, 0xCE, 0x4C, 0x00, 0x00});
  EXPECT_EQ(n.sdo({0x40, 0x67, 0x2C, 0x00}), (Bytes{0x43, 0x67, 0x2C, 0x00, 0x08, 0x00, 0x00, 0x00}));
  EXPECT_EQ(n.sdo({0x40, 0x74, 0x2C, 0x00}), (Bytes{0x43, 0x74, 0x2C, 0x00, 0x98, 0x99, 0x00, 0x00}));
  EXPECT_EQ(n.raw(0x2C72), 24575);
  EXPECT_EQ(n.raw(0x2046), 19662);
}

TEST(VtvpcdPdo, ShortRpdoIgnoredWithoutEmcyLongerOneAccepted) {  // checklist 23
  vtest::Vtvpcd n;
  n.start();
  n->take();
  n->send(0x23F, {0x08, 0x00, 0x00, 0x00});
  n->run_ms(10);
  EXPECT_TRUE(n->take().empty());
  EXPECT_EQ(n.raw(0x2C67), 0);
  n->send(0x33F, {0x10, 0x00, 0x00, 0x00});  // RPDO2 maps 8 bytes
  EXPECT_EQ(n.raw(0x2C72), 0);
  n->send(Frame::remote(0x23F, 8));
  EXPECT_EQ(n.raw(0x2C67), 0);
  // RPDO3/4 map nothing: any frame on them is accepted and changes nothing.
  n->send(0x43F, {1, 2, 3});
  n->send(0x53F, {});
  n->run_ms(10);
  EXPECT_TRUE(n->take().empty());
}

TEST(VtvpcdPdo, RpdoLongerThanItsMappingSurplusIgnored) {  // digest §2.9
  vtest::Vtvpcd n;
  // RPDO1 cut to the Trigger alone (DS-301 procedure, Pre-operational): 4 mapped bytes.
  ASSERT_EQ(n->write(0x1600, 0, 0, 1), 0u);
  ASSERT_EQ(n->write(0x1600, 0, 1, 1), 0u);
  n.start();
  n->take();
  // The TV38 frame, 8 bytes: the Trigger is taken, bytes 4-7 (formerly Pressure CMD) are not.
  n->send(0x23F, {0x08, 0x00, 0x00, 0x00, 0x98, 0x99, 0x00, 0x00});
  n->run_ms(10);
  EXPECT_TRUE(n->take().empty());  // no EMCY, no reply
  EXPECT_EQ(n.sdo({0x40, 0x67, 0x2C, 0x00}), (Bytes{0x43, 0x67, 0x2C, 0x00, 0x08, 0x00, 0x00, 0x00}));
  EXPECT_EQ(n.sdo({0x40, 0x74, 0x2C, 0x00}), (Bytes{0x43, 0x74, 0x2C, 0x00, 0xFD, 0xBF, 0x01, 0x00}));
  EXPECT_EQ(n.raw(0x2F2F), n.raw(0x2004));  // set 3 is in use
  // Surplus on a 2-byte configured slot, too.
  vtest::Vtvpcd m({{"rpdo_area", "0x2C72:2"}});
  m.start();
  m->send(0x23F, {0x00, 0xC0, 0x1F, 0xFF, 0x11, 0x22, 0x33, 0x44});
  EXPECT_EQ(m.sdo({0x40, 0x72, 0x2C, 0x00}), (Bytes{0x43, 0x72, 0x2C, 0x00, 0x00, 0xC0, 0xFF, 0xFF}));
  EXPECT_EQ(m.sdo({0x40, 0x2A, 0x2F, 0x00}), (Bytes{0x4B, 0x2A, 0x2F, 0x00, 0x00, 0x00, 0x00, 0x00}));
}

TEST(VtvpcdPdo, SyncAndRemoteRequestsTriggerNothing) {  // checklist 24, A19
  vtest::Vtvpcd n;
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n.start();
  n->run_ms(50);
  n->take();
  n->send(0x080, {});
  n->send(0x080, {0x01});
  n->send(Frame::remote(0x1BF, 8));
  n->send(Frame::remote(0x2BF, 4));
  n->send(0x100, {0, 0, 0, 0, 0, 0});  // TIME: ignored
  EXPECT_TRUE(n->take().empty());
  n->run_ms(49);
  EXPECT_TRUE(n->take().empty());
  n->run_ms(1);
  EXPECT_EQ(n->take().size(), 1u);
}

TEST(VtvpcdPdo, MappingReadback) {  // checklist 40, TV37
  vtest::Vtvpcd n;
  EXPECT_EQ(n.sdo({0x40, 0x00, 0x1A, 0x01}), (Bytes{0x43, 0x00, 0x1A, 0x01, 0x20, 0x00, 0x0F, 0x2F}));
  EXPECT_EQ(n->read_u(0x1A00, 2), 0x2F260020u);
  EXPECT_EQ(n->read_u(0x1A01, 0), 1u);
  EXPECT_EQ(n->read_u(0x1A01, 1), 0x2F190020u);
  EXPECT_EQ(n->read_u(0x1A02, 0), 0u);
  EXPECT_EQ(n->read_u(0x1A03, 0), 0u);
  EXPECT_EQ(n->read_u(0x1600, 0), 2u);
  EXPECT_EQ(n->read_u(0x1600, 1), 0x2C670020u);
  EXPECT_EQ(n->read_u(0x1600, 2), 0x2C740020u);
  EXPECT_EQ(n->read_u(0x1601, 1), 0x2C720020u);
  EXPECT_EQ(n->read_u(0x1601, 2), 0x20460020u);
  EXPECT_EQ(n->read_u(0x1602, 0), 0u);
  EXPECT_EQ(n.device->node().pdo().tpdo_length(1), 8);
  EXPECT_EQ(n.device->node().pdo().tpdo_length(2), 4);
}

TEST(VtvpcdPdo, MappingBySdoInPreOperationalOnly) {  // A16
  vtest::Vtvpcd n({{"builtin_plant", "false"}});
  EXPECT_EQ(n->write(0x1A02, 1, 0x2F070020u, 4), 0u);  // sub 0 is 0: entries writable
  EXPECT_EQ(n->write(0x1A02, 2, 0x2F270010u, 4), 0u);
  EXPECT_EQ(n->write(0x1A02, 3, 0x2F260008u, 4), 0x06040043u);  // 8 bits
  EXPECT_EQ(n->write(0x1A02, 3, 0x30000020u, 4), 0x06040041u);  // no such object
  EXPECT_EQ(n->write(0x1A02, 3, 0x2F070120u, 4), 0x06040041u);  // sub-index 1
  EXPECT_EQ(n->write(0x1A02, 3, 0x10010008u, 4), 0x06040043u);
  EXPECT_EQ(n->write(0x1A02, 3, 0x10000020u, 4), 0x06040041u);  // communication object
  EXPECT_EQ(n->write(0x1A02, 3, 0x2F0F0020u, 4), 0u);           // 10 bytes in total
  EXPECT_EQ(n->write(0x1A02, 0, 3, 1), 0x06040042u);
  EXPECT_EQ(n->write(0x1A02, 0, 9, 1), 0x06090031u);
  EXPECT_EQ(n->write(0x1A02, 0, 2, 1), 0u);
  EXPECT_EQ(n->write(0x1A02, 1, 0x2F190020u, 4), 0x08000022u);  // sub 0 not 0
  EXPECT_EQ(n->write(0x1602, 1, 0x2F070020u, 4), 0x06040041u);  // read-only object in an RPDO
  EXPECT_EQ(n->write(0x1602, 1, 0x2C990010u, 4), 0u);
  EXPECT_EQ(n->write(0x1602, 0, 1, 1), 0u);
  EXPECT_EQ(n->write(0x1802, 5, 10, 2), 0u);
  n.set("swivel_angle", -0.5);  // A4VSO range: the reading is still -50 %
  n.start();
  EXPECT_EQ(n->write(0x1A02, 0, 0, 1), 0x08000022u);  // Operational: refused
  EXPECT_EQ(n->write(0x1802, 1, 0x80000000u | 0x3BFu, 4), 0x08000022u);
  n->run_ms(10);
  const auto frames = n->take();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0], Frame(0x3BF, {0x00, 0xC0, 0xFF, 0xFF, 0x00, 0x01}));  // act. Angle -16384, Discrete Inputs 0x0100
  // RPDO3 carries res. Angle CMD (BUS) as 2 bytes: sign-extended into the 4-byte object.
  n->send(0x43F, {0x00, 0xC0});
  EXPECT_EQ(n.raw(0x2C99), -16384);
  // The SDO-made mapping is volatile: a communication reset restores the Bus Manager image.
  n->send(0x000, {0x82, 0x3F});
  n->run_ms(50);
  EXPECT_EQ(n->read_u(0x1A02, 0), 0u);
  EXPECT_EQ(n->read_u(0x1602, 0), 0u);
}

TEST(VtvpcdPdo, CobIdRules) {
  vtest::Vtvpcd n;
  EXPECT_EQ(n->write(0x1400, 1, 0x2000023Fu, 4), 0x06040043u);  // 29-bit
  EXPECT_EQ(n->write(0x1400, 1, 0x800u, 4), 0x06040043u);
  EXPECT_EQ(n->write(0x1400, 1, 0x80000000u | 0x23F, 4), 0u);  // RPDO1 off
  n.start();
  n->send(0x23F, {0x08, 0, 0, 0, 0x98, 0x99, 0, 0});
  EXPECT_EQ(n.raw(0x2C67), 0);
  EXPECT_EQ(n->write(0x1400, 1, 0x23Fu, 4), 0x08000022u);
  n->send(0x000, {0x80, 0x3F});
  EXPECT_EQ(n->write(0x1400, 1, 0x240u, 4), 0u);  // another identifier, no invalidation needed
  n.start();
  n->send(0x240, {0x08, 0, 0, 0, 0x98, 0x99, 0, 0});
  EXPECT_EQ(n.raw(0x2C67), 8);
  // Power-on restores the predefined connection set.
  n.device->power_off();
  n.power_on();
  EXPECT_EQ(n->read_u(0x1400, 1), 0x23Fu);
}

TEST(VtvpcdPdo, MappingObjectsCanBeHidden) {  // expose_mapping_objects = false
  vtest::Vtvpcd n({{"expose_mapping_objects", "false"}});
  EXPECT_EQ(n.sdo({0x40, 0x00, 0x1A, 0x01}), (Bytes{0x80, 0x00, 0x1A, 0x01, 0x00, 0x00, 0x02, 0x06}));
  EXPECT_EQ(n.sdo({0x2F, 0x00, 0x16, 0x00, 0, 0, 0, 0}), (Bytes{0x80, 0x00, 0x16, 0x00, 0x00, 0x00, 0x02, 0x06}));
  ASSERT_EQ(n->write(0x1800, 5, 10, 2), 0u);
  n.start();
  n->run_ms(10);
  EXPECT_EQ(n->take().size(), 1u);  // the mapping still works
}

TEST(VtvpcdPdo, ConfiguredAreasWithTwoByteSlots) {
  vtest::Vtvpcd n({{"tpdo_area", "0x2F26:2,0x2C68:2,0x2F07:2"}, {"rpdo_area", "0x2C72:2,0x2F2A:2"}, {"builtin_plant", "false"}});
  EXPECT_EQ(n->read_u(0x1A00, 0), 3u);
  EXPECT_EQ(n->read_u(0x1A00, 3), 0x2F070010u);
  EXPECT_EQ(n->read_u(0x1600, 1), 0x2C720010u);
  ASSERT_EQ(n->write(0x1800, 5, 10, 2), 0u);
  n.set("swivel_angle", 0.5);
  n.start();
  n->send(0x23F, {0x00, 0xC0, 0x1F, 0xFF});
  EXPECT_EQ(n.raw(0x2C72), -16384);  // 2-byte slot sign-extended
  EXPECT_EQ(n.raw(0x2F2A), -225);
  n->run_ms(10);
  const auto f = n->take();
  ASSERT_EQ(f.size(), 1u);
  ASSERT_EQ(f[0].data.size(), 6u);
  EXPECT_EQ(f[0].data[4], 0x00);  // low 16 bits of act. Angle 16384
  EXPECT_EQ(f[0].data[5], 0x40);
}
