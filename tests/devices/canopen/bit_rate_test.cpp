// Node-level bit-rate behaviour, frame level: automatic bit-rate detection
// (LssPolicy::automatic_bit_rate_index), a node on a different rate than the bus, and bus-off.
#include <gtest/gtest.h>

#include "devices/canopen/lss_slave.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

namespace {
canopen::LssPolicy auto_detecting() {
  canopen::LssPolicy p;
  p.bit_rates.set(9);
  p.automatic_bit_rate_index = 9;
  return p;
}
}  // namespace

TEST(BitRate, AutomaticDetectionKeepsTheNodePassiveUntilAnotherNodeSends) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.node().enable_lss(auto_detecting());
  h.node().lss()->set_default_bit_rate(9);
  h.power_on();
  h.run_ms(5000);
  EXPECT_TRUE(h.take().empty());  // no boot-up, no heartbeat while detecting
  EXPECT_TRUE(h.node().detecting_bit_rate());
  // The first frame only serves detection: this SDO request gets no answer, boot-up follows.
  h.send(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
  EXPECT_FALSE(h.node().detecting_bit_rate());
  EXPECT_EQ(h.read_u(0x1000, 0), 0x191u);
}

TEST(BitRate, DetectionAdoptsTheBusRateAndNmtResetsDoNotRestartIt) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.bus().set_bit_rate_kbit(250);
  h.node().enable_lss(auto_detecting());
  h.node().lss()->set_default_bit_rate(9);
  h.power_on();
  h.send(0x080, {});
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h.node().bit_rate_kbit(), 250u);
  h.nmt(0x81, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});  // Reset Node: boots at once
}

TEST(BitRate, WithoutTheKnobANodeBootsAtOnce) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.node().enable_lss(canopen::LssPolicy{});
  h.power_on();
  EXPECT_EQ(h.take(), Frames{Frame(0x705, {0x00})});
}

TEST(BitRate, ANodeOnAnotherRateThanTheBusNeitherSendsNorReceives) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.bus().set_bit_rate_kbit(500);
  h.node().enable_lss(canopen::LssPolicy{});
  h.node().lss()->set_default_bit_rate(3);  // 250 kbit/s
  h.power_on();
  EXPECT_TRUE(h.take().empty());
  h.send(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(h.take().empty());
  h.bus().set_bit_rate_kbit(250);  // the master switches to the node's rate
  EXPECT_EQ(h.read_u(0x1000, 0), 0x191u);
}

TEST(BitRate, BusOffBlocksFramesBothWaysUntilCleared) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.take();
  h.node().set_bus_off(true);
  h.send(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
  h.run_ms(5);
  EXPECT_TRUE(h.take().empty());
  h.node().set_bus_off(false);
  EXPECT_EQ(h.read_u(0x1000, 0), 0x191u);
}
