// RPDO/TPDO and SYNC, frame level (node 5). Default generic node:
//   TPDO1 0x185 type 255: 0x6000 (U16) + 0x6002 (U8)      TPDO2 0x285 type 1: 0x6001 (I32)
//   RPDO1 0x205 type 255: 0x6001 (I32) + 0x6000 (U16)     RPDO2 0x305 type 0: 0x6000 (U16)
#include "devices/canopen/pdo_service.h"

#include <gtest/gtest.h>

#include "devices/canopen/emergency.h"
#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

namespace {
class PdoTest : public ::testing::Test {
 protected:
  PdoTest() : h(vtest::make_generic_od(), {}, 5) {
    h.power_on();
    h.take();
  }
  /// NMT start plus one tick (event-driven TPDOs go out in the tick after the transition).
  void operational() {
    h.nmt(0x01, 5);
    h.run_ticks(1);
  }
  vtest::CanopenHarness h;
};
}  // namespace

TEST_F(PdoTest, EventTpdoGoesOutOnEnteringOperationalAndOnChange) {
  operational();
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x34, 0x12, 0x55})});
  h.run_ms(10);
  EXPECT_TRUE(h.take().empty());
  h.node().od().set<std::uint16_t>(0x6000, 0, 0x0102);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x02, 0x01, 0x55})});
}

TEST_F(PdoTest, InhibitTimeSpacesEventPdos) {
  ASSERT_EQ(h.write(0x1800, 3, 50, 2), 0u);  // 5 ms
  operational();
  EXPECT_EQ(h.take().size(), 1u);  // sent on entering Operational: inhibit runs from here
  h.node().od().set<std::uint16_t>(0x6000, 0, 1);
  h.run_ms(4);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x01, 0x00, 0x55})});
}

TEST_F(PdoTest, EventTimerRepeatsTheTpdo) {
  ASSERT_EQ(h.write(0x1800, 5, 20, 2), 0u);
  operational();
  EXPECT_EQ(h.take().size(), 1u);
  h.run_ms(60);
  EXPECT_EQ(h.take_times().size(), 3u);  // at 20, 40 and 60 ms after the one on entering Operational
}

TEST_F(PdoTest, SyncTpdoEveryNthSync) {
  ASSERT_EQ(h.write(0x1801, 2, 2, 1), 0u);  // every 2nd SYNC
  operational();
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, -2);
  h.send(0x080, {});
  EXPECT_TRUE(h.take().empty());
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0xFE, 0xFF, 0xFF, 0xFF})});
  // SYNC in Pre-operational: nothing.
  h.nmt(0x80, 5);
  h.send(0x080, {});
  h.send(0x080, {});
  EXPECT_TRUE(h.take().empty());
}

TEST_F(PdoTest, Type252SendsOnRemoteRequestWhatTheLastSyncSampled) {
  ASSERT_EQ(h.write(0x1801, 2, 252, 1), 0u);
  operational();
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, 7);
  h.send(0x080, {});
  EXPECT_TRUE(h.take().empty());  // sampled, not sent
  h.node().od().set<std::int32_t>(0x6001, 0, 9);
  h.send(Frame::remote(0x285, 4));
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x07, 0, 0, 0})});
  h.send(0x080, {});
  h.send(Frame::remote(0x285, 4));
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x09, 0, 0, 0})});
}

TEST_F(PdoTest, Type253SendsOnRemoteRequestOnlyWithCurrentData) {
  ASSERT_EQ(h.write(0x1801, 2, 253, 1), 0u);
  operational();
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, 7);
  h.send(0x080, {});
  h.run_ms(50);
  EXPECT_TRUE(h.take().empty());  // neither SYNC nor time nor a change sends it
  h.node().od().set<std::int32_t>(0x6001, 0, 8);
  h.send(Frame::remote(0x285, 4));
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x08, 0, 0, 0})});
}

TEST_F(PdoTest, Type254IsEventDrivenLike255) {
  ASSERT_EQ(h.write(0x1800, 2, 254, 1), 0u);
  ASSERT_EQ(h.write(0x1800, 5, 30, 2), 0u);
  operational();
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x34, 0x12, 0x55})});
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0, 0, 0, 0})});  // only TPDO2 (type 1) answers a SYNC
  h.node().od().set<std::uint8_t>(0x6002, 0, 0x56);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x34, 0x12, 0x56})});
  h.run_ms(30);
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x34, 0x12, 0x56})});  // event timer
}

TEST_F(PdoTest, PaddedTpdosGoOutWithEightBytesAndAnswerEightByteRemoteRequests) {
  h.node().policy().pdo.pad_tpdo_to_8 = true;
  operational();
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x34, 0x12, 0x55, 0, 0, 0, 0, 0})});
  h.send(Frame::remote(0x285, 8));
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0, 0, 0, 0, 0, 0, 0, 0})});
  h.node().policy().pdo.rtr_dlc_mismatch = canopen::PdoPolicy::RtrDlcMismatch::Ignore;
  h.send(Frame::remote(0x285, 4));  // the mapped length is no longer the PDO's length
  EXPECT_TRUE(h.take().empty());
}

namespace {
// Node 5 with 0x1019 and TPDO2 (0x285, 0x6001) carrying a SYNC start value.
class SyncCounterTest : public ::testing::Test {
 protected:
  SyncCounterTest() : h(vtest::make_generic_od(true), {}, 5) {
    h.power_on();
    h.take();
  }
  void sync(std::uint8_t counter) { h.send(0x080, {counter}); }
  vtest::CanopenHarness h;
};
}  // namespace

TEST_F(SyncCounterTest, OverflowValueRejectsReservedValues) {
  EXPECT_EQ(h.write(0x1019, 0, 1, 1), 0x06090030u);
  EXPECT_EQ(h.write(0x1019, 0, 241, 1), 0x06090030u);
  EXPECT_EQ(h.write(0x1019, 0, 240, 1), 0u);
  EXPECT_EQ(h.write(0x1019, 0, 0, 1), 0u);
}

TEST_F(SyncCounterTest, StartValueIsWrittenOnlyWhileThePdoIsInvalid) {
  EXPECT_EQ(h.write(0x1801, 6, 3, 1), 0x06090030u);  // PDO valid
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  EXPECT_EQ(h.write(0x1801, 6, 241, 1), 0x06090031u);
  EXPECT_EQ(h.write(0x1801, 6, 3, 1), 0u);
  EXPECT_EQ(h.read(0x1801, 6), std::vector<std::uint8_t>{3});
}

TEST_F(SyncCounterTest, FirstTransmissionWaitsForTheStartValueThenEveryNth) {
  ASSERT_EQ(h.write(0x1019, 0, 4, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1801, 2, 2, 1), 0u);  // every 2nd SYNC
  ASSERT_EQ(h.write(0x1801, 6, 3, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  h.node().od().set<std::int32_t>(0x6001, 0, 5);
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();  // TPDO1 (event-driven) on entering Operational
  const Frame tpdo2(0x285, {0x05, 0, 0, 0});
  std::vector<bool> sent;
  for (std::uint8_t counter : {1, 2, 3, 4, 1, 2, 3, 4}) {
    sync(counter);
    const Frames out = h.take();
    EXPECT_LE(out.size(), 1u);
    sent.push_back(out == Frames{tpdo2});
  }
  // Counter 3 is the first SYNC counted: sent on it, then on every 2nd SYNC after it.
  EXPECT_EQ(sent, (std::vector<bool>{false, false, true, false, true, false, true, false}));
}

TEST_F(SyncCounterTest, APdoMadeValidAgainWaitsForItsStartValueAgain) {
  ASSERT_EQ(h.write(0x1019, 0, 4, 1), 0u);
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  sync(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0, 0, 0, 0})});  // type 1, no start value yet
  // Reconfigured in Operational: invalid, start value 4, valid again.
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1801, 6, 4, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  sync(2);
  sync(3);
  EXPECT_TRUE(h.take().empty());
  sync(4);
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0, 0, 0, 0})});
}

TEST_F(SyncCounterTest, WithoutAStartValueTheFirstSyncCounts) {
  ASSERT_EQ(h.write(0x1019, 0, 4, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 2, 2, 1), 0u);
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  sync(3);
  EXPECT_TRUE(h.take().empty());
  sync(4);
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0, 0, 0, 0})});
}

TEST_F(SyncCounterTest, SyncOfTheWrongLengthRaisesEmcy8240AndIsNotActedOn) {
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  // 0x1019 = 0: a SYNC carries no data.
  sync(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x40, 0x82, 0x11, 0, 0, 0, 0, 0})});  // no TPDO2
  h.send(0x080, {});
  EXPECT_EQ(h.take(), (Frames{Frame(0x085, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0}), Frame(0x285, {0, 0, 0, 0})}));
  // 0x1019 = 4: a SYNC carries the counter.
  h.nmt(0x80, 5);
  ASSERT_EQ(h.write(0x1019, 0, 4, 1), 0u);
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x40, 0x82, 0x11, 0, 0, 0, 0, 0})});
  sync(1);
  EXPECT_EQ(h.take(), (Frames{Frame(0x085, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0}), Frame(0x285, {0, 0, 0, 0})}));
}

TEST_F(PdoTest, RpdoWritesMappedObjectsAndSynchronousRpdoWaitsForSync) {
  operational();
  h.take();
  h.send(0x205, {0x78, 0x56, 0x34, 0x12, 0xAA, 0xBB});
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 0x12345678u);
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0xBBAA);
  h.send(0x305, {0x11, 0x22});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0xBBAA);
  h.send(0x080, {});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x2211);
}

TEST_F(PdoTest, RpdoLengthErrorsRaiseEmcy8210And8220) {
  operational();
  h.take();
  h.send(0x205, {1, 2, 3});
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0x10, 0x82, 0x11, 0, 0, 0, 0, 0})});
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 0u);
  h.send(0x205, {1, 0, 0, 0, 2, 0});  // correct length: error clears
  EXPECT_EQ(h.take(), Frames{Frame(0x085, {0, 0, 0, 0, 0, 0, 0, 0})});
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 1u);
}

TEST_F(PdoTest, RpdoTooLongRaises8220ButIsProcessed) {
  operational();
  h.take();
  h.send(0x205, {1, 0, 0, 0, 2, 0, 9, 9});
  const auto frames = h.take();
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.front(), Frame(0x085, {0x20, 0x82, 0x11, 0, 0, 0, 0, 0}));
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 1u);
}

TEST_F(PdoTest, RemoteRequestAnswersWithCurrentData) {
  operational();
  h.take();
  h.send(Frame::remote(0x285, 4));
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0, 0, 0, 0})});
}

TEST_F(PdoTest, DynamicMappingProcedure) {
  // CiA 301: disable the PDO, sub0 = 0, write entries, sub0 = n, enable.
  EXPECT_EQ(h.write(0x1A00, 1, 0x60010020, 4), 0x08000022u);  // PDO still valid
  ASSERT_EQ(h.write(0x1800, 1, 0x80000185, 4), 0u);
  EXPECT_EQ(h.write(0x1A00, 1, 0x60010020, 4), 0x08000022u);  // sub0 still 2
  ASSERT_EQ(h.write(0x1A00, 0, 0, 1), 0u);
  EXPECT_EQ(h.write(0x1A00, 1, 0x60030010, 4), 0x06040041u);  // not mappable
  EXPECT_EQ(h.write(0x1A00, 1, 0x7FFF0010, 4), 0x06040041u);  // does not exist
  EXPECT_EQ(h.write(0x1A00, 1, 0x60010010, 4), 0x06040041u);  // wrong length
  ASSERT_EQ(h.write(0x1A00, 1, 0x60010020, 4), 0u);
  ASSERT_EQ(h.write(0x1A00, 2, 0x60010020, 4), 0u);
  ASSERT_EQ(h.write(0x1A00, 3, 0x60000010, 4), 0u);
  EXPECT_EQ(h.write(0x1A00, 0, 3, 1), 0x06040042u);  // 80 bits
  ASSERT_EQ(h.write(0x1A00, 0, 2, 1), 0u);
  EXPECT_EQ(h.write(0x1A00, 0, 9, 1), 0x06090031u);  // more entries than exist
  ASSERT_EQ(h.write(0x1800, 1, 0x00000185, 4), 0u);
  EXPECT_EQ(h.node().pdo().tpdo_length(1), 8);
  operational();
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST_F(PdoTest, CobIdChangeRequiresInvalidPdoAndTypesAreChecked) {
  EXPECT_EQ(h.write(0x1800, 1, 0x00000190, 4), 0x06090030u);
  ASSERT_EQ(h.write(0x1800, 1, 0x80000185, 4), 0u);
  ASSERT_EQ(h.write(0x1800, 1, 0x00000190, 4), 0u);
  EXPECT_EQ(h.write(0x1800, 2, 241, 1), 0x06090030u);
  EXPECT_EQ(h.write(0x1400, 2, 252, 1), 0x06090030u);  // RTR types are TPDO-only
  operational();
  EXPECT_EQ(h.take(), Frames{Frame(0x190, {0x34, 0x12, 0x55})});
}

TEST_F(PdoTest, DisabledPdoIsNotSentOrReceived) {
  ASSERT_EQ(h.write(0x1800, 1, 0x80000185, 4), 0u);
  ASSERT_EQ(h.write(0x1400, 1, 0x80000205, 4), 0u);
  operational();
  h.send(0x205, {1, 0, 0, 0, 2, 0});
  EXPECT_TRUE(h.take().empty());
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 0u);
}

TEST_F(PdoTest, Type255WithoutEventTimerCanMeanPdoOff) {
  h.node().policy().pdo.type255_off_without_timer = true;
  h.node().policy().pdo.send_async_on_operational = true;
  operational();
  h.node().od().set<std::uint16_t>(0x6000, 0, 0x0102);
  h.run_ms(10);
  EXPECT_TRUE(h.take().empty());  // type 255, event timer 0: off (no initial, no change frames)
  h.nmt(0x80, 5);
  ASSERT_EQ(h.write(0x1800, 5, 20, 2), 0u);
  operational();
  h.take();
  h.run_ms(40);
  EXPECT_EQ(h.take().size(), 2u);  // with a timer it runs (the knob does not touch timers)
}

TEST_F(PdoTest, MinimumSpacingPacesChangeDrivenTransmission) {
  h.node().pdo().set_min_spacing(1, sim::milliseconds(10));
  operational();
  h.take();
  for (int i = 0; i < 20; ++i) {
    h.node().od().set<std::uint16_t>(0x6000, 0, static_cast<std::uint16_t>(i + 1));
    h.run_ticks(1);
  }
  const auto times = h.take_times();
  ASSERT_EQ(times.size(), 2u);  // changes every ms, at most one frame per 10 ms
  EXPECT_GE(times[1] - times[0], sim::milliseconds(10));
}

TEST_F(PdoTest, RestartEventTimerCountsFromNow) {
  ASSERT_EQ(h.write(0x1800, 5, 100, 2), 0u);
  operational();
  h.take();
  h.run_ms(60);
  h.node().pdo().restart_event_timer(1);
  h.run_ms(99);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take().size(), 1u);
}

TEST_F(PdoTest, ChangeBaselineOnOperationalSendsOnlyRealChanges) {
  h.node().policy().pdo.change_baseline_on_operational = true;
  operational();
  h.run_ms(10);
  EXPECT_TRUE(h.take().empty());
  h.node().od().set<std::uint16_t>(0x6000, 0, 0x0102);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x02, 0x01, 0x55})});
}

TEST_F(PdoTest, PdoSwitchedOffByTheDeviceIsSilentButReadsValid) {
  auto& pdo = h.node().pdo();
  pdo.set_active(canopen::PdoDirection::Receive, 1, false);
  pdo.set_active(canopen::PdoDirection::Transmit, 2, false);
  EXPECT_FALSE(pdo.active(canopen::PdoDirection::Receive, 1));
  operational();
  h.take();
  // RPDO1 is ignored, its COB-ID still reads valid.
  h.send(0x205, {0x78, 0x56, 0x34, 0x12, 0xAA, 0xBB});
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 0u);
  EXPECT_EQ(h.read_u(0x1400, 1), 0x205u);
  // TPDO2 (every SYNC) neither goes out on SYNC nor answers a remote request.
  ASSERT_EQ(h.read_u(0x1801, 2), 1u);
  h.send(0x080, {});
  h.send(Frame::remote(0x285, 4));
  EXPECT_TRUE(h.take().empty());
  // Switched on again, both work.
  pdo.set_active(canopen::PdoDirection::Receive, 1, true);
  pdo.set_active(canopen::PdoDirection::Transmit, 2, true);
  h.send(0x205, {0x78, 0x56, 0x34, 0x12, 0xAA, 0xBB});
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x6001), 0x12345678u);
  h.take();
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x78, 0x56, 0x34, 0x12})});
}

TEST(PdoPolicyKnobs, TpdoRemoteRequestsCanBeIgnored) {
  canopen::NodePolicy policy;
  policy.pdo.tpdo_remote_requests = false;
  vtest::CanopenHarness h(vtest::make_generic_od(), policy, 5);
  h.power_on();
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  h.send(Frame::remote(0x185, 3));
  h.send(Frame::remote(0x285, 4));
  EXPECT_TRUE(h.take().empty());
}

TEST(PdoPolicyKnobs, EventTimerWriteRestartsThePeriod) {
  for (const bool restart : {false, true}) {
    canopen::NodePolicy policy;
    policy.pdo.type255 = {.on_change = false, .after_rpdo = false, .on_timer = true};
    policy.pdo.event_timer_restart_on_write = restart;
    vtest::CanopenHarness h(vtest::make_generic_od(), policy, 5);
    h.power_on();
    h.nmt(0x01, 5);  // event timer 0: nothing scheduled
    h.run_ms(50);
    h.take();
    const auto written = h.now();
    ASSERT_EQ(h.write(0x1800, 5, 20, 2), 0u);
    h.run_ms(45);
    const auto times = h.take_times();
    ASSERT_FALSE(times.empty());
    if (restart) {
      ASSERT_EQ(times.size(), 2u);
      EXPECT_EQ((times[0] - written).count(), 20000);  // one full period after the write
      EXPECT_EQ((times[1] - times[0]).count(), 20000);
    } else {
      EXPECT_LE((times[0] - written).count(), 1000);  // the stale deadline fires at once
    }
  }
}

// Parameters and mappings rewritten by SDO while the node runs in Operational with SYNCs
// flowing: each change takes effect at once, TPDOs move between the SYNC-driven and the
// event-driven kinds, and a remapped RPDO writes its new objects.
TEST_F(PdoTest, TpdoRemappedWhileOperationalSendsTheNewMappingFromTheNextSync) {
  operational();
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, -2);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0xFE, 0xFF, 0xFF, 0xFF})});
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);  // invalid: no longer sent
  h.send(0x080, {});
  EXPECT_TRUE(h.take().empty());
  ASSERT_EQ(h.write(0x1A01, 0, 0, 1), 0u);
  ASSERT_EQ(h.write(0x1A01, 1, 0x60020008, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 2, 0x60000010, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 3, 0x60010020, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 3, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  EXPECT_EQ(h.node().pdo().tpdo_length(2), 7);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x55, 0x34, 0x12, 0xFE, 0xFF, 0xFF, 0xFF})});
  // Mapping count 0 while valid is refused; invalid with count 0: nothing is sent.
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 0, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  h.send(0x080, {});
  h.run_ms(5);
  EXPECT_TRUE(h.take().empty());
}

TEST_F(PdoTest, TransmissionTypeChangedWhileOperationalMovesTheTpdoBetweenSyncAndEvents) {
  operational();
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x34, 0x12, 0x55})});
  // TPDO1 from event-driven (255) to every SYNC (1): changes alone no longer send it.
  ASSERT_EQ(h.write(0x1800, 2, 1, 1), 0u);
  h.node().od().set<std::uint16_t>(0x6000, 0, 0x0A0B);
  h.run_ms(3);
  EXPECT_TRUE(h.take().empty());
  h.send(0x080, {});
  EXPECT_EQ(h.take(), (Frames{Frame(0x185, {0x0B, 0x0A, 0x55}), Frame(0x285, {0, 0, 0, 0})}));
  // TPDO2 from SYNC (1) to event-driven (255) with an event timer: SYNCs no longer send it.
  ASSERT_EQ(h.write(0x1801, 2, 255, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 5, 10, 2), 0u);
  h.take();
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x0B, 0x0A, 0x55})});
  h.node().od().set<std::int32_t>(0x6001, 0, 3);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x03, 0, 0, 0})});
  h.run_ms(10);
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x03, 0, 0, 0})});  // the event timer
  // Type 0 (acyclic synchronous): sent at a SYNC, and only when the data changed.
  ASSERT_EQ(h.write(0x1801, 2, 0, 1), 0u);
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, 4);
  h.run_ms(20);
  EXPECT_TRUE(h.take().empty());
  h.send(0x080, {});
  EXPECT_EQ(h.take(), (Frames{Frame(0x185, {0x0B, 0x0A, 0x55}), Frame(0x285, {0x04, 0, 0, 0})}));
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x0B, 0x0A, 0x55})});
}

TEST_F(PdoTest, TpdoCobIdChangedWhileOperationalGoesOutOnTheNewIdentifier) {
  operational();
  h.take();
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000391, 4), 0u);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x391, {0, 0, 0, 0})});
  h.send(Frame::remote(0x391, 4));
  EXPECT_EQ(h.take(), Frames{Frame(0x391, {0, 0, 0, 0})});
  h.send(Frame::remote(0x285, 4));  // the old identifier is no longer routed
  EXPECT_TRUE(h.take().empty());
}

TEST_F(PdoTest, RpdoRemappedWhileOperationalWritesItsNewObjects) {
  operational();
  h.take();
  h.send(0x205, {0x01, 0x00, 0x00, 0x00, 0x02, 0x00});
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), 1);
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 2u);
  ASSERT_EQ(h.write(0x1400, 1, 0x80000205, 4), 0u);
  h.send(0x205, {0x07, 0x00, 0x00, 0x00, 0x08, 0x00});  // invalid: ignored
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), 1);
  ASSERT_EQ(h.write(0x1600, 0, 0, 1), 0u);
  ASSERT_EQ(h.write(0x1600, 1, 0x60000010, 4), 0u);
  ASSERT_EQ(h.write(0x1600, 2, 0x00050008, 4), 0u);  // dummy UNSIGNED8: a byte skipped
  ASSERT_EQ(h.write(0x1600, 3, 0x60010020, 4), 0u);
  ASSERT_EQ(h.write(0x1600, 0, 3, 1), 0u);
  ASSERT_EQ(h.write(0x1400, 1, 0x00000205, 4), 0u);
  EXPECT_EQ(h.node().pdo().rpdo_length(1), 7);
  h.send(0x205, {0x34, 0x12, 0xEE, 0xFC, 0xFF, 0xFF, 0xFF});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x1234u);
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), -4);
  // Now synchronous: the values wait for the SYNC.
  ASSERT_EQ(h.write(0x1400, 2, 1, 1), 0u);
  h.send(0x205, {0x78, 0x56, 0x00, 0x05, 0x00, 0x00, 0x00});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x1234u);
  h.send(0x080, {});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x5678u);
  EXPECT_EQ(h.node().od().get<std::int32_t>(0x6001), 5);
}

// The dictionary's object set changing while PDOs map its entries: the PDOs resolve their
// mappings again before the next frame, so no pointer to a removed entry is followed.
TEST_F(PdoTest, ObjectRemovedWhileMappedIsNoLongerSentOrWritten) {
  operational();
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, -2);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0xFE, 0xFF, 0xFF, 0xFF})});
  h.node().od().remove_object(0x6001);  // mapped into TPDO2 and RPDO1
  h.send(0x080, {});
  EXPECT_TRUE(h.take().empty());  // TPDO2's stored mapping no longer resolves: nothing to send
  EXPECT_EQ(h.node().pdo().tpdo_length(2), 0);
  h.send(0x205, {0x01, 0x00, 0x00, 0x00, 0x02, 0x00});
  EXPECT_EQ(h.node().pdo().rpdo_length(1), 0);
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x1234u);  // RPDO1 writes nothing now
}

TEST_F(PdoTest, ObjectReplacedWhileMappedIsTheOneThePdosCarry) {
  operational();
  h.take();
  auto& od = h.node().od();
  od.remove_object(0x6001);
  od.add_var(0x6001, "Command I32 again", canopen::DataType::Integer32, canopen::Access::ReadWrite, 0x11223344, true);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0x44, 0x33, 0x22, 0x11})});
  h.send(0x205, {0x05, 0x00, 0x00, 0x00, 0x02, 0x00});
  EXPECT_EQ(od.get<std::int32_t>(0x6001), 5);  // the new entry
  od.remove_entry(0x1800, 5);                  // TPDO1's event timer, read every tick
  h.run_ms(5);
  h.take();  // TPDO1 sent the 0x6000 the RPDO changed
  od.set<std::uint16_t>(0x6000, 0, 0x0102);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x185, {0x02, 0x01, 0x55})});
}

TEST_F(PdoTest, RemappedViaSdoTheTpdoCarriesTheNewObjectAndNotTheOld) {
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 0, 1), 0u);
  ASSERT_EQ(h.write(0x1A01, 1, 0x60000010, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 1, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  operational();
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, -2);  // the old object: not in the frame
  h.node().od().set<std::uint16_t>(0x6000, 0, 0xBEEF);
  h.send(0x080, {});
  Frames frames = h.take();
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.back(), Frame(0x285, {0xEF, 0xBE}));
}

TEST(PdoWidthConversion, NarrowObjectsInWideSlotsAreSignOrZeroExtendedAndWideOnesTruncated) {
  canopen::NodePolicy policy;
  policy.pdo.width_conversion = true;
  vtest::CanopenHarness h(vtest::make_generic_od(), policy, 5);
  h.power_on();
  h.take();
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 0, 1), 0u);
  ASSERT_EQ(h.write(0x1A01, 1, 0x60010030, 4), 0u);  // I32 in 48 bits: sign-extended
  ASSERT_EQ(h.write(0x1A01, 2, 0x60020010, 4), 0u);  // U8 in 16 bits: zero-extended
  ASSERT_EQ(h.write(0x1A01, 0, 2, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  h.node().od().set<std::int32_t>(0x6001, 0, -3);
  h.node().od().set<std::uint8_t>(0x6002, 0, 0x81);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0xFD, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x81, 0x00})});
  h.node().od().set<std::int32_t>(0x6001, 0, 0x7FFFFFFF);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0xFF, 0xFF, 0xFF, 0x7F, 0x00, 0x00, 0x81, 0x00})});
  // A wide object in a narrow slot keeps its low bytes.
  ASSERT_EQ(h.write(0x1801, 1, 0x80000285, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 0, 1), 0u);
  ASSERT_EQ(h.write(0x1A01, 1, 0x60010010, 4), 0u);
  ASSERT_EQ(h.write(0x1A01, 0, 1, 1), 0u);
  ASSERT_EQ(h.write(0x1801, 1, 0x00000285, 4), 0u);
  h.send(0x080, {});
  EXPECT_EQ(h.take(), Frames{Frame(0x285, {0xFF, 0xFF})});
}

TEST(PdoService, WiredFromAboveRaisesTheLengthEmcyAndReportsTheRpdo) {
  vtest::FakeNodeLinks links;
  links.status.node_id = 5;
  links.status.nmt_state = canopen::NmtState::Operational;
  auto od = vtest::make_generic_od();
  canopen::PdoPolicy policy;
  canopen::PdoService pdo(od, policy, links.status, links, links, links, links);
  pdo.bind_objects();
  pdo.reload();
  pdo.on_rpdo(1, Frame(0x205, {1, 2, 3}).to_can(), sim::Time{});  // mapped: 6 bytes
  EXPECT_EQ(links.raised, std::vector<std::uint16_t>{0x8210});
  EXPECT_TRUE(links.rpdos.empty());
  pdo.on_rpdo(1, Frame(0x205, {0x78, 0x56, 0x34, 0x12, 0xCD, 0xAB}).to_can(), sim::Time{});
  EXPECT_EQ(links.rpdos, std::vector<int>{1});
  EXPECT_EQ(od.get<std::int32_t>(0x6001, 0), 0x12345678);
}
