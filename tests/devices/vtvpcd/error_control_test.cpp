// Heartbeat, node guarding and life guarding with the card's reaction to a bus timeout
// (manual §3.1; digest §2.4, §2.5, A20, A21; checklist 25-28; TV31-TV34, TV40).
#include <gtest/gtest.h>

#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using vtest::Frame;
using vtest::Frames;

namespace {
std::vector<std::uint8_t> bytes(std::initializer_list<std::uint8_t> b) { return b; }
}  // namespace

TEST(VtvpcdHeartbeat, ProducerReplacesGuarding) {  // checklist 25, TV31, TV40
  vtest::Vtvpcd n;
  EXPECT_EQ(n.sdo({0x40, 0x17, 0x10, 0x00}), bytes({0x4B, 0x17, 0x10, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x2B, 0x17, 0x10, 0x00, 0xE8, 0x03, 0, 0}), bytes({0x60, 0x17, 0x10, 0x00, 0, 0, 0, 0}));
  const auto written = n->now();
  n->run_ms(3001);
  const auto times = n->take_times();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ((times[0] - written).count(), 1000000);
  EXPECT_EQ((times[1] - times[0]).count(), 1000000);
  EXPECT_EQ((times[2] - times[1]).count(), 1000000);
  n->run_ms(1000);
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x7F})});
  n.start();
  n->send(Frame::remote(0x73F, 1));  // not answered while the heartbeat runs
  n->run_ms(1000);
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x05})});
  ASSERT_EQ(n->write(0x1017, 0, 0, 2), 0u);
  n->run_ms(3000);
  EXPECT_TRUE(n->take().empty());
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x05})});
}

TEST(VtvpcdLifeGuarding, TimeoutIsFault16WithAStopAndOneEmcy) {  // checklist 26-28, TV32-TV34
  vtest::Vtvpcd n;
  n->run_ms(50);
  ASSERT_GT(n.raw(0x2F26) & 0x03, 0);  // DO1 + OK while enabled and fault-free
  EXPECT_EQ(n.sdo({0x2B, 0x0C, 0x10, 0x00, 0x64, 0x00, 0, 0}), bytes({0x60, 0x0C, 0x10, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x2F, 0x0D, 0x10, 0x00, 0x03, 0x00, 0, 0}), bytes({0x60, 0x0D, 0x10, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x0D, 0x10, 0x00}), bytes({0x4F, 0x0D, 0x10, 0x00, 0x03, 0, 0, 0}));
  n->send(Frame::remote(0x73F, 1));
  EXPECT_EQ(n->take(), Frames{Frame(0x73F, {0x7F})});
  const auto armed = n->now();
  n->run_ms(300);
  EXPECT_TRUE(n->take().empty());  // life time 300 ms not yet exceeded
  n->run_ms(2);
  const auto frames = n->take();
  const auto t = n->now();
  ASSERT_EQ(frames, Frames{Frame(0x0BF, {0x00, 0x81, 0x11, 0, 0, 0, 0, 0})});
  EXPECT_LE((t - armed).count(), 302000);
  EXPECT_EQ(n.sdo({0x40, 0x01, 0x10, 0x00}), bytes({0x4F, 0x01, 0x10, 0x00, 0x11, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x03, 0x10, 0x00}), bytes({0x4F, 0x03, 0x10, 0x00, 0x01, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x03, 0x10, 0x01}), bytes({0x43, 0x03, 0x10, 0x01, 0x00, 0x81, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x03, 0x10, 0x02}), bytes({0x80, 0x03, 0x10, 0x02, 0x11, 0x00, 0x09, 0x06}));
  n->run_ms(1);
  EXPECT_EQ(n.sdo({0x40, 0x68, 0x2C, 0x00}), bytes({0x4B, 0x68, 0x2C, 0x00, 0x10, 0x11, 0, 0}));
  EXPECT_EQ(n.raw(0x2F1F), 0);           // valve CMD: de-energised
  EXPECT_EQ(n.raw(0x2F26) & 0x03, 0);    // OK and DO1 cleared
  EXPECT_LT(n.dev().control().spool_command, 0.0);

  // Checklist 27: no repetition while it stays.
  n->run_ms(5000);
  EXPECT_TRUE(n->take().empty());

  // Checklist 28: guarding again clears the cause, the Enable edge acknowledges.
  n->send(Frame::remote(0x73F, 1));
  n->take();
  n->run_ms(10);
  EXPECT_TRUE(n->take().empty());  // latched (fault_latch = true)
  n.set("enable", 0);
  n->run_ms(5);
  n->send(Frame::remote(0x73F, 1));
  n.set("enable", 1);
  n->run_ms(2);
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0x7F}), Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})}));
  EXPECT_EQ(n.sdo({0x40, 0x01, 0x10, 0x00}), bytes({0x4F, 0x01, 0x10, 0x00, 0x00, 0, 0, 0}));
  EXPECT_EQ(n.sdo({0x40, 0x03, 0x10, 0x00}), bytes({0x4F, 0x03, 0x10, 0x00, 0x00, 0, 0, 0}));
  EXPECT_EQ(n.raw(0x2C68), 0);
  EXPECT_EQ(n.raw(0x2F26) & 0x03, 0x03);
}

TEST(VtvpcdLifeGuarding, WithoutLatchTheFaultClearsWhenGuardingResumes) {
  vtest::Vtvpcd n({{"fault_latch", "false"}});
  ASSERT_EQ(n->write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(n->write(0x100D, 0, 3, 1), 0u);
  n->send(Frame::remote(0x73F, 1));
  n->run_ms(305);
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0x7F}), Frame(0x0BF, {0x00, 0x81, 0x11, 0, 0, 0, 0, 0})}));
  n->send(Frame::remote(0x73F, 1));
  n->run_ms(1);
  EXPECT_EQ(n->take(), (Frames{Frame(0x73F, {0xFF}), Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})}));
}

TEST(VtvpcdLifeGuarding, ReportOnlyReactionKeepsTheValveEnergised) {  // timeout_reaction = report
  vtest::Vtvpcd n({{"timeout_reaction", "report"}});
  ASSERT_EQ(n.write4(0x2C72, 16384), 0u);
  ASSERT_EQ(n->write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(n->write(0x100D, 0, 2, 1), 0u);
  n->send(Frame::remote(0x73F, 1));
  n->run_ms(210);
  EXPECT_EQ(n->take().back(), Frame(0x0BF, {0x00, 0x81, 0x11, 0, 0, 0, 0, 0}));
  EXPECT_EQ(n.raw(0x2C68), 0x1110);
  EXPECT_TRUE(n.dev().control().energised);
  EXPECT_EQ(n.raw(0x2F26) & 0x03, 0x01);  // DO1 on, OK off
}

TEST(VtvpcdLifeGuarding, SwitchingGuardingOffRemovesTheCause) {
  vtest::Vtvpcd n;
  ASSERT_EQ(n->write(0x100C, 0, 100, 2), 0u);
  ASSERT_EQ(n->write(0x100D, 0, 2, 1), 0u);
  n->send(Frame::remote(0x73F, 1));
  n->run_ms(210);
  n->take();
  ASSERT_EQ(n->write(0x100C, 0, 0, 2), 0u);
  n.set("enable", 0);
  n->run_ms(2);
  n.set("enable", 1);
  n->run_ms(2);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
}

TEST(VtvpcdHeartbeatConsumer, MissingHeartbeatIsFault16) {
  vtest::Vtvpcd n;
  // Consumer: producer node 1, 100 ms.
  ASSERT_EQ(n->write(0x1016, 1, 0x00010064u, 4), 0u);
  n->run_ms(500);
  EXPECT_TRUE(n->take().empty());  // monitoring starts with the first heartbeat
  n->send(0x701, {0x05});
  n->run_ms(100);
  EXPECT_TRUE(n->take().empty());
  n->run_ms(2);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0x00, 0x81, 0x11, 0, 0, 0, 0, 0})});
  EXPECT_EQ(n.raw(0x2C68), 0x1110);
  n->send(0x701, {0x05});
  n.set("enable", 0);
  n->run_ms(2);
  n.set("enable", 1);
  n->run_ms(2);
  EXPECT_EQ(n->take(), Frames{Frame(0x0BF, {0, 0, 0, 0, 0, 0, 0, 0})});
}
