// The stack on a bit-timed bus (sim::Bus, BusTiming::Bit) in virtual time: its CiA 301 reactions
// to the bus's fault confinement (error passive, bus-off and recovery) and the latency that a
// lower-identifier flood adds to its heartbeat and its SYNC TPDO.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

namespace {

// Destroys the next `count` transmission attempts of one endpoint.
struct BitErrors : sim::FrameFilter {
  int endpoint = 0;
  int count = 0;
  Verdict on_send(sim::CanFrame&, int, sim::Time) override { return {}; }
  bool on_transmit(const sim::CanFrame&, int from, sim::Time) override {
    if (from != endpoint || count == 0) return false;
    --count;
    return true;
  }
};

// The first frame `id` whose data starts with `prefix`; -1 if none.
std::ptrdiff_t find_frame(const Frames& frames, std::uint32_t id, std::vector<std::uint8_t> prefix) {
  const auto it = std::find_if(frames.begin(), frames.end(), [&](const Frame& f) {
    return f.id == id && f.data.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), f.data.begin());
  });
  return it == frames.end() ? -1 : it - frames.begin();
}

// Node 5 with heartbeat every 10 ms and no event TPDO, then on a 500 kbit/s timed bus.
void setup(vtest::CanopenHarness& h) {
  h.power_on();
  ASSERT_EQ(h.write(0x1800, 1, 0x80000185u, 4), 0u);
  ASSERT_EQ(h.write(0x1017, 0, 10, 2), 0u);
  h.take();
  h.bus().set_timing(sim::BusTiming::Bit, 500000);
}

}  // namespace

TEST(CanController, ErrorPassiveSendsEmcy8120AndErrorActiveClearsIt) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  setup(h);
  BitErrors errors;
  errors.endpoint = h.node().endpoint();
  errors.count = 16;  // TEC 128: error passive; the retransmission then succeeds: 127, active
  h.bus().set_filter(&errors);
  h.run_ms(15);
  const auto frames = h.take();
  const auto hb = find_frame(frames, 0x705, {0x7F});
  const auto passive = find_frame(frames, 0x085, {0x20, 0x81});
  ASSERT_GE(hb, 0);
  ASSERT_GT(passive, hb) << ::testing::PrintToString(frames);
  EXPECT_EQ(frames[static_cast<std::size_t>(passive)].data[2], 0x11);  // generic + communication
  const auto cleared = find_frame(frames, 0x085, {0x00, 0x00});
  EXPECT_GT(cleared, passive);
  EXPECT_EQ(h.bus().stats().error_frames, 16u);
  EXPECT_EQ(h.bus().counters(h.node().endpoint()).state, sim::ErrorState::Active);
  EXPECT_LT(h.bus().counters(h.node().endpoint()).tec, 128u);
}

TEST(CanController, BusOffSilencesTheNodeAndRecoverySendsEmcy8140) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  setup(h);
  BitErrors errors;
  errors.endpoint = h.node().endpoint();
  errors.count = 32;  // TEC 256 > 255: bus-off
  h.bus().set_filter(&errors);
  // 32 attempts of ~70 bits at 2 us: bus-off within 5 ms of the first heartbeat.
  int ms = 0;
  while (!h.node().bus_off() && ms < 30) {
    h.run_ms(1);
    ++ms;
  }
  ASSERT_TRUE(h.node().bus_off());
  EXPECT_EQ(h.bus().counters(h.node().endpoint()).state, sim::ErrorState::BusOff);
  EXPECT_TRUE(h.take().empty());  // nothing got through
  // 128 x 11 recessive bits = 2.816 ms of idle bus: back, EMCY 8140h, the heartbeat resumes.
  h.run_ms(4);
  EXPECT_FALSE(h.node().bus_off());
  h.run_ms(20);
  const auto frames = h.take();
  const auto recovered = find_frame(frames, 0x085, {0x40, 0x81});
  ASSERT_GE(recovered, 0) << ::testing::PrintToString(frames);
  EXPECT_GT(find_frame(frames, 0x705, {0x7F}), recovered);
  EXPECT_EQ(h.bus().counters(h.node().endpoint()).bus_off_events, 1u);
}

namespace {

struct Latency {
  double tpdo_us = 0;       ///< SYNC sent -> TPDO2 received, mean
  double heartbeat_us = 0;  ///< heartbeat produced -> received, mean
  std::size_t tpdos = 0;
  std::size_t heartbeats = 0;
  std::size_t syncs = 0;
  std::uint64_t flood_overflow = 0;
};

struct Probe : sim::FrameReceiver {
  std::vector<std::pair<sim::CanFrame, sim::Time>> got;
  void on_frame(const sim::CanFrame& f, sim::Time t) override { got.emplace_back(f, t); }
};

constexpr std::int64_t kPeriodUs = 10000;

// 125 kbit/s; a master sends SYNC every 10 ms and, at the same instant, a flooder queues `flood`
// 8-byte frames with identifier 0x010 (they win every arbitration against SYNC, the TPDO and the
// heartbeat). Node 5: TPDO2 (0x285) on every SYNC, heartbeat every 10 ms. `phase_us` is the
// heartbeat's production instant modulo 10 ms: learnt by the run without flood (-1 on entry).
Latency measure(int flood, std::int64_t& phase_us) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  EXPECT_EQ(h.write(0x1800, 1, 0x80000185u, 4), 0u);
  EXPECT_EQ(h.write(0x1017, 0, 10, 2), 0u);
  h.nmt(0x01, 5);
  h.take();
  auto& bus = h.bus();
  bus.set_timing(sim::BusTiming::Bit, 125000);
  Probe probe;
  const int sync_ep = bus.attach(&probe);
  Probe flooder;
  const int flood_ep = bus.attach(&flooder);
  Latency out;
  const std::int64_t start_us = h.now().time_since_epoch().count();
  for (int ms = 0; ms < 1000; ++ms) {
    if (ms % 10 == 0) {
      for (int i = 0; i < flood; ++i) bus.send(flood_ep, sim::CanFrame::data_frame(0x010, {1, 2, 3, 4, 5, 6, 7, 8}), h.now());
      bus.send(sync_ep, sim::CanFrame::data_frame(0x080, {}), h.now());
      ++out.syncs;
    }
    h.run_ms(1);
    h.take();
  }
  double tpdo_sum = 0, hb_sum = 0;
  for (const auto& [f, t] : probe.got) {
    const std::int64_t us = t.time_since_epoch().count();
    if (f.id == 0x285) {
      ++out.tpdos;
      tpdo_sum += static_cast<double>((us - start_us) % kPeriodUs);  // SYNCs go out on the 10 ms grid
    } else if (f.id == 0x705) {
      if (phase_us < 0) phase_us = (us / 1000 * 1000) % kPeriodUs;  // no flood: within its tick
      ++out.heartbeats;
      hb_sum += static_cast<double>(((us - phase_us) % kPeriodUs + kPeriodUs) % kPeriodUs);
    }
  }
  if (out.tpdos) out.tpdo_us = tpdo_sum / static_cast<double>(out.tpdos);
  if (out.heartbeats) out.heartbeat_us = hb_sum / static_cast<double>(out.heartbeats);
  out.flood_overflow = bus.counters(flood_ep).tx_queue_overflow;
  return out;
}

}  // namespace

TEST(CanController, HeartbeatAndTpdoLatencyGrowAsALowerIdFloodTakesTheBus) {
  std::int64_t phase = -1;
  const auto idle = measure(0, phase);
  const auto some = measure(3, phase);
  const auto most = measure(6, phase);
  EXPECT_EQ(idle.tpdos, idle.syncs);
  EXPECT_GE(idle.heartbeats, 99u);
  EXPECT_LT(idle.tpdo_us, 2000);
  EXPECT_LT(idle.heartbeat_us, 1000);
  // Every 8-byte flood frame holds the bus for at least 111 bits (888 us) first.
  EXPECT_GT(some.tpdo_us, idle.tpdo_us + 3 * 888) << some.tpdo_us;
  EXPECT_GT(most.tpdo_us, some.tpdo_us + 3 * 888) << most.tpdo_us;
  EXPECT_GT(some.heartbeat_us, idle.heartbeat_us + 2 * 888) << some.heartbeat_us;
  EXPECT_GT(most.heartbeat_us, some.heartbeat_us + 2 * 888) << most.heartbeat_us;
  EXPECT_EQ(most.tpdos, most.syncs);
  // More flood than the bus carries: its queue overflows and never empties; SYNC, TPDO and
  // heartbeat lose every arbitration.
  const auto saturated = measure(12, phase);
  EXPECT_GT(saturated.flood_overflow, 0u);
  EXPECT_LT(saturated.tpdos, saturated.syncs / 10);
  EXPECT_LT(saturated.heartbeats, 10u);
}
