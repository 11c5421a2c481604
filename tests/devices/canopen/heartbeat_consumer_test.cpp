#include "devices/canopen/heartbeat_consumer.h"

#include <gtest/gtest.h>

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
