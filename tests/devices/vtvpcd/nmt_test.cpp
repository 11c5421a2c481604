// Boot-up, NMT commands and addressing, resets (manual §3.1; digest §2.3; checklist 1-7, 39; TV1-TV5).
#include <gtest/gtest.h>

#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using vtest::Frame;
using vtest::Frames;

TEST(VtvpcdNmt, PowerOnSendsOneBootUpAfter300MsThenSilence) {  // checklist 1, TV1
  vtest::Vtvpcd n({}, 0, false);
  const auto on = n->now();
  n.device->power_on(on);
  n->run_ms(300);
  EXPECT_TRUE(n->take().empty());
  n->run_ms(1);
  const auto times = n->take_times();
  ASSERT_EQ(times.size(), 1u);
  EXPECT_EQ((times[0] - on).count(), 300000);
  n.device->power_off();
  n.power_on();
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x00})});
  n->run_ms(5000);
  EXPECT_TRUE(n->take().empty());
  EXPECT_EQ(n.device->node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST(VtvpcdNmt, GuardingTogglesAndStartKeepsTheToggle) {  // checklist 2, 3; TV2, TV3
  vtest::Vtvpcd n;
  for (int i = 0; i < 3; ++i) n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0x7F}), Frame(0x73F, {0xFF}), Frame(0x73F, {0x7F})}));
  n->send(0x000, {0x01, 0x3F});
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x85})});
  EXPECT_EQ(n.device->node().nmt_state(), canopen::NmtState::Operational);
}

TEST(VtvpcdNmt, CommandsForOtherNodesAreIgnored) {  // checklist 4
  vtest::Vtvpcd n;
  n->send(0x000, {0x01, 0x05});
  n->send(Frame::remote(0x73F, 1));
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0x7F}), Frame(0x73F, {0xFF})}));
}

TEST(VtvpcdNmt, MalformedAndUnknownNmtFramesAreIgnored) {
  vtest::Vtvpcd n;
  n->send(0x000, {0x01});              // DLC 1
  n->send(0x000, {0x01, 0x3F, 0x00});  // DLC 3
  n->send(0x000, {0x03, 0x3F});        // no such command
  n->send(0x000, {0x81, 0x40});        // another node
  n->run_ms(200);
  EXPECT_TRUE(n->take().empty());
  EXPECT_EQ(n.device->node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST(VtvpcdNmt, BroadcastPreOperationalStopsTpdos) {  // checklist 5, TV4
  vtest::Vtvpcd n;
  ASSERT_EQ(n->write(0x1800, 5, 10, 2), 0u);
  n.start();
  n->run_ms(30);
  EXPECT_EQ(n->take().size(), 3u);
  n->send(0x000, {0x80, 0x00});
  n->run_ms(100);
  EXPECT_TRUE(n->take().empty());
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x7F})});
}

TEST(VtvpcdNmt, ResetCommunicationKeepsManufacturerValues) {  // checklist 6
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, -16384), 0u);
  ASSERT_EQ(n.write4(0x2001, 12345), 0u);
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n->send(Frame::remote(0x73F, 1));
  n->take();
  n->send(0x000, {0x82, 0x3F});
  n->run_ms(100);
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x00})});
  EXPECT_EQ(n.sdo({0x40, 0x00, 0x18, 0x05}), (std::vector<std::uint8_t>{0x4B, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x72, 0x2C, 0x00}), (std::vector<std::uint8_t>{0x43, 0x72, 0x2C, 0x00, 0x00, 0xC0, 0xFF, 0xFF}));
  EXPECT_EQ(n.sdo({0x40, 0x01, 0x20, 0x00}), (std::vector<std::uint8_t>{0x43, 0x01, 0x20, 0x00, 0x39, 0x30, 0x00, 0x00}));  // 12345
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x7F})});  // toggle restarted
}

TEST(VtvpcdNmt, ResetOfAmplifierCardRestoresTheConfigurationImage) {  // checklist 7, TV5
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2C72, -16384), 0u);
  ASSERT_EQ(n.write4(0x2001, 12345), 0u);
  ASSERT_EQ(n.write4(0x2C74, 1000), 0u);
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n->send(Frame::remote(0x73F, 1));
  n->take();
  n->send(0x000, {0x81, 0x3F});
  n->run_ms(100);
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x00})});
  // Read over SDO as the checklist does: the configuration image (0, 0, 114685 = 0x0001BFFD, 0).
  EXPECT_EQ(n.sdo({0x40, 0x72, 0x2C, 0x00}), (std::vector<std::uint8_t>{0x43, 0x72, 0x2C, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(n.sdo({0x40, 0x01, 0x20, 0x00}), (std::vector<std::uint8_t>{0x43, 0x01, 0x20, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(n.sdo({0x40, 0x74, 0x2C, 0x00}), (std::vector<std::uint8_t>{0x43, 0x74, 0x2C, 0x00, 0xFD, 0xBF, 0x01, 0x00}));
  EXPECT_EQ(n.sdo({0x40, 0x00, 0x18, 0x05}), (std::vector<std::uint8_t>{0x4B, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x7F})});
}

TEST(VtvpcdNmt, PowerCycleLosesEverythingWrittenOverTheBus) {
  vtest::Vtvpcd n;
  ASSERT_EQ(n.write4(0x2046, 19662), 0u);
  ASSERT_EQ(n->write(0x1017, 0, 500, 2), 0u);
  n.device->power_off();
  n->run_ms(1000);
  n.power_on();
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x00})});
  EXPECT_EQ(n.raw(0x2046), 32770);
  EXPECT_EQ(n.od().get<std::uint16_t>(0x1017), 0u);
  // No store/restore objects exist.
  EXPECT_EQ(n.sdo({0x40, 0x10, 0x10, 0x01}), (std::vector<std::uint8_t>{0x80, 0x10, 0x10, 0x01, 0x00, 0x00, 0x02, 0x06}));
  EXPECT_EQ(n.sdo({0x23, 0x10, 0x10, 0x01, 's', 'a', 'v', 'e'}),
            (std::vector<std::uint8_t>{0x80, 0x10, 0x10, 0x01, 0x00, 0x00, 0x02, 0x06}));
  EXPECT_EQ(n.sdo({0x40, 0x11, 0x10, 0x01}), (std::vector<std::uint8_t>{0x80, 0x11, 0x10, 0x01, 0x00, 0x00, 0x02, 0x06}));
}

TEST(VtvpcdNmt, StoppedAnswersOnlyNmtAndGuarding) {
  vtest::Vtvpcd n;
  n->send(0x000, {0x02, 0x3F});
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x04})});
  n->send(0x63F, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(n->take().empty());
  n.dev().inject_fault("pressure_b_sensor_break", true);
  n->run_ms(10);
  EXPECT_TRUE(n->take().empty());  // no EMCY in Stopped
  n->send(0x000, {0x80, 0x3F});
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0xFF})});
}

TEST(VtvpcdNmt, StopCanBeSwitchedOff) {
  vtest::Vtvpcd n({{"nmt_stop_supported", "false"}});
  n->send(0x000, {0x02, 0x3F});
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x7F})});
}

TEST(VtvpcdNmt, NodeFiveUsesItsOwnIdentifiers) {  // checklist 39
  vtest::Vtvpcd n({}, 5, false);
  n.power_on();
  EXPECT_EQ(n->take(), Frames{Frame(0x705, {0x00})});
  n->send(0x63F, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(n->take().empty());
  n->send(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(n->take(), Frames{Frame(0x585, {0x43, 0x00, 0x10, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(n->read_u(0x1014, 0), 0x85u);
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  n->send(0x000, {0x01, 0x05});
  n->run_ms(101);
  const auto frames = n->take();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].id, 0x185u);
  n.dev().inject_fault("lvdt_fault", true);
  n->run_ms(2);
  EXPECT_EQ(n->take(), Frames{Frame(0x085, {0x36, 0x52, 0x81, 0, 0, 0, 0, 0})});
}

TEST(VtvpcdNmt, CanControllerResetKeepsCommunicationParameters) {  // nmt_82 = can_controller
  vtest::Vtvpcd n({{"nmt_82", "can_controller"}});
  ASSERT_EQ(n->write(0x1800, 5, 100, 2), 0u);
  ASSERT_EQ(n->write(0x100C, 0, 200, 2), 0u);
  n->send(0x000, {0x82, 0x3F});
  n->run_ms(50);
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x00})});
  EXPECT_EQ(n->read_u(0x1800, 5), 100u);
  EXPECT_EQ(n->read_u(0x100C, 0), 200u);
  n.start();
  n->run_ms(100);
  EXPECT_EQ(n->take().size(), 1u);  // TPDO1 still runs on its timer
}

TEST(VtvpcdNmt, NodeIdObjectAppliesAtTheNextResetAndIsLostAtPowerOff) {  // node_id_object (A3)
  vtest::Vtvpcd n({{"node_id_object", "0x5000"}});
  EXPECT_EQ(n->read_u(0x5000, 0), 63u);
  EXPECT_EQ(n->write(0x5000, 0, 0, 1), 0x06090032u);
  EXPECT_EQ(n->write(0x5000, 0, 128, 1), 0x06090031u);
  ASSERT_EQ(n->write(0x5000, 0, 5, 1), 0u);
  EXPECT_EQ(n.id(), 63);  // not before a reset
  n->send(0x000, {0x82, 0x3F});
  n->run_ms(50);
  EXPECT_EQ(n->take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(n->read_u(0x5000, 0), 5u);
  n->send(0x000, {0x81, 0x05});
  n->run_ms(50);
  EXPECT_EQ(n->take(), Frames{Frame(0x705, {0x00})});  // reset node keeps the bus-set ID
  n.device->power_off();
  n.power_on();
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x00})});
}
