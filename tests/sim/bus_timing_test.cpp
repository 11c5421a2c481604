// The bit-timed in-process bus: frame durations, arbitration, transmit queues, throughput at
// saturation, bus load and ISO 11898-1 fault confinement, all in virtual time.
#include <gtest/gtest.h>

#include <vector>

#include "sim/bus.h"
#include "sim/can_bit_timing.h"

namespace {

using sim::Bus;
using sim::BusTiming;
using sim::CanFrame;
using sim::ErrorState;
using sim::Time;

struct Recorder : sim::FrameReceiver {
  std::vector<CanFrame> frames;
  std::vector<Time> times;
  std::vector<ErrorState> states;
  void on_frame(const CanFrame& f, Time t) override {
    frames.push_back(f);
    times.push_back(t);
  }
  void on_error_state(ErrorState s, Time) override { states.push_back(s); }
};

Time at_us(std::int64_t us) { return Time{sim::Duration{us}}; }

// Destroys the first `count` transmission attempts of one endpoint.
struct BitErrors : sim::FrameFilter {
  int endpoint = 0;
  int count = 0;
  Verdict on_send(CanFrame&, int, Time) override { return {}; }
  bool on_transmit(const CanFrame&, int from, Time) override {
    if (from != endpoint || count == 0) return false;
    --count;
    return true;
  }
};

}  // namespace

TEST(BusTiming, FrameIsDeliveredAtTheEndOfItsEof) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 500000);  // 2 us per bit
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  const auto f = CanFrame::data_frame(0x000, {});  // 53 bits, 50 up to the end of EOF
  bus.send(ea, f, at_us(1000));
  EXPECT_EQ(bus.deliver(at_us(1000)), 0u);  // sent at this instant: not decided yet
  EXPECT_EQ(bus.deliver(at_us(1099)), 0u);  // started at 1000, ends at 1100
  EXPECT_EQ(bus.deliver(at_us(1100)), 1u);
  ASSERT_EQ(b.times.size(), 1u);
  EXPECT_EQ(b.times[0], at_us(1100));
  EXPECT_EQ(bus.stats().busy_bits, 53u);
}

TEST(BusTiming, SimultaneousFramesGoInArbitrationOrder) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 125000);  // 8 us per bit
  Recorder rx;
  std::vector<Recorder> nodes(5);
  std::vector<int> ep;
  for (auto& n : nodes) ep.push_back(bus.attach(&n));
  bus.attach(&rx);
  auto ext = CanFrame::data_frame(0x100u << 18, {1});
  const std::vector<CanFrame> sent = {CanFrame::data_frame(0x300, {1}), ext, CanFrame::remote_frame(0x100, 1),
                                      CanFrame::data_frame(0x100, {1}), CanFrame::data_frame(0x080, {1})};
  for (std::size_t i = 0; i < sent.size(); ++i) bus.send(ep[i], sent[i], at_us(0));
  bus.deliver(at_us(100000));
  ASSERT_EQ(rx.frames.size(), 5u);
  EXPECT_EQ(rx.frames[0], sent[4]);  // 0x080
  EXPECT_EQ(rx.frames[1], sent[3]);  // 0x100 data
  EXPECT_EQ(rx.frames[2], sent[2]);  // 0x100 remote
  EXPECT_EQ(rx.frames[3], sent[1]);  // extended, base 0x100
  EXPECT_EQ(rx.frames[4], sent[0]);  // 0x300
  // Back to back: each starts when the previous one's intermission ends.
  std::int64_t start_bits = 0;
  for (std::size_t i = 0; i < rx.frames.size(); ++i) {
    const auto bits = sim::frame_bits(rx.frames[i]);
    EXPECT_EQ(rx.times[i], at_us((start_bits + bits.until_eof()) * 8)) << i;
    start_bits += bits.total();
  }
}

TEST(BusTiming, TransmitQueueIsFifoAndBounded) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 1000000);
  bus.set_tx_queue_depth(3);
  Recorder a, b, rx;
  const int ea = bus.attach(&a);
  const int eb = bus.attach(&b);
  bus.attach(&rx);
  // A FIFO: a's 0x050 waits behind its 0x400 even though b's 0x200 is pending.
  bus.send(ea, CanFrame::data_frame(0x400, {}), at_us(0));
  bus.send(ea, CanFrame::data_frame(0x050, {}), at_us(0));
  bus.send(eb, CanFrame::data_frame(0x200, {}), at_us(0));
  bus.send(ea, CanFrame::data_frame(0x051, {}), at_us(0));
  bus.send(ea, CanFrame::data_frame(0x052, {}), at_us(0));  // the fourth: the queue is full
  EXPECT_EQ(bus.stats().tx_queue_overflow, 1u);
  EXPECT_EQ(bus.counters(ea).tx_queue_overflow, 1u);
  EXPECT_EQ(bus.pending_frames(), 4u);
  bus.deliver(at_us(10000));
  ASSERT_EQ(rx.frames.size(), 4u);
  EXPECT_EQ(rx.frames[0].id, 0x200u);
  EXPECT_EQ(rx.frames[1].id, 0x400u);
  EXPECT_EQ(rx.frames[2].id, 0x050u);
  EXPECT_EQ(rx.frames[3].id, 0x051u);
}

// A saturated bus delivers its bit rate divided by the frame mix's mean length, within 1 %.
void saturate(std::uint32_t rate) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, rate);
  Recorder src, rx;
  const int es = bus.attach(&src);
  bus.attach(&rx);
  const std::vector<CanFrame> mix = {CanFrame::data_frame(0x181, {1, 2, 3, 4, 5, 6, 7, 8}),
                                     CanFrame::data_frame(0x000, {}), CanFrame::data_frame(0x701, {5}),
                                     CanFrame::data_frame(0x12345, {0xFF, 0, 0xFF}),
                                     CanFrame::data_frame(0x581, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0, 0})};
  double mix_bits = 0;
  for (const auto& f : mix) mix_bits += sim::frame_bits(f).total();
  const double theory = static_cast<double>(rate) / (mix_bits / static_cast<double>(mix.size()));
  std::size_t next = 0;
  for (std::int64_t ms = 0; ms < 2000; ++ms) {
    while (bus.pending_frames() < Bus::kDefaultTxQueue) bus.send(es, mix[next++ % mix.size()], at_us(ms * 1000));
    bus.deliver(at_us(ms * 1000));
  }
  const double fps = static_cast<double>(rx.frames.size()) / 2.0;
  EXPECT_NEAR(fps, theory, theory * 0.01) << rate;
  EXPECT_GT(bus.load(), 0.99);
  EXPECT_GT(bus.mean_load(), 0.99);
  EXPECT_EQ(bus.stats().tx_queue_overflow, 0u);
}

TEST(BusTiming, SaturatedBusAt125kDeliversTheTheoreticalFrameRate) { saturate(125000); }
TEST(BusTiming, SaturatedBusAt1MDeliversTheTheoreticalFrameRate) { saturate(1000000); }

TEST(BusTiming, LoadIsTheOccupiedFractionOfTheWindow) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 125000);
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  const auto f = CanFrame::data_frame(0x086, {0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0x55});  // 111 bits
  for (std::int64_t ms = 0; ms < 500; ++ms) {
    if (ms % 2 == 0) bus.send(ea, f, at_us(ms * 1000));
    bus.deliver(at_us(ms * 1000));
  }
  EXPECT_NEAR(bus.load(), 111 * 8e-6 / 2e-3, 0.01);  // 888 us every 2 ms
  const auto traffic = bus.traffic();
  ASSERT_EQ(traffic.size(), 1u);
  EXPECT_EQ(traffic[0].id, 0x086u);
  EXPECT_EQ(traffic[0].bits, traffic[0].frames * 111);
}

TEST(BusTiming, IdealBusCountsLoadToo) {
  Bus bus("main");  // ideal: zero time, but the bits are counted
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  bus.set_timing(BusTiming::Ideal, 125000);
  bus.send(ea, CanFrame::data_frame(0x000, {}), at_us(0));
  EXPECT_EQ(bus.deliver(at_us(0)), 1u);
  EXPECT_EQ(b.times.at(0), at_us(0));
  EXPECT_EQ(bus.stats().busy_bits, 53u);
}

// Fault confinement: 16 destroyed attempts take the transmitter to TEC 128 (error passive); its
// successes count back down to 127 (error active). Every error frame occupies the bus.
TEST(BusTiming, ErrorPassiveAndBack) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 500000);
  Recorder a, b;
  const int ea = bus.attach(&a);
  const int eb = bus.attach(&b);
  BitErrors errors;
  errors.endpoint = ea;
  errors.count = 16;
  bus.set_filter(&errors);
  const auto f = CanFrame::data_frame(0x181, {1, 2});
  bus.send(ea, f, at_us(0));
  bus.deliver(at_us(100000));
  // Retransmitted until it got through: one frame, 16 error frames before it.
  ASSERT_EQ(b.frames.size(), 1u);
  EXPECT_EQ(bus.stats().error_frames, 16u);
  EXPECT_EQ(bus.counters(ea).tec, 127u);  // 16 * 8 - 1
  EXPECT_EQ(bus.counters(eb).rec, 15u);   // 16 - 1
  ASSERT_EQ(a.states.size(), 2u);
  EXPECT_EQ(a.states[0], ErrorState::Passive);
  EXPECT_EQ(a.states[1], ErrorState::Active);
  const auto bits = sim::frame_bits(f);
  const unsigned error_bits = bits.stuffed_region + bits.stuff_bits + 3 + sim::kErrorFrameBits;
  // The successful frame waited for 16 error frames, and after the last one (sent passive) the
  // 8-bit suspend transmission.
  EXPECT_EQ(b.times[0], at_us((16 * error_bits + 8 + bits.until_eof()) * 2));
  EXPECT_EQ(bus.stats().busy_bits, 16 * error_bits + bits.total());
}

// 32 destroyed attempts: TEC 256 > 255, bus-off; the queue is flushed, nothing is sent or
// received; after 128 sequences of 11 recessive bits the controller is error active again.
TEST(BusTiming, BusOffAndRecovery) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 500000);
  Recorder a, b;
  const int ea = bus.attach(&a);
  const int eb = bus.attach(&b);
  BitErrors errors;
  errors.endpoint = ea;
  errors.count = 1000;
  bus.set_filter(&errors);
  bus.send(ea, CanFrame::data_frame(0x181, {1, 2}), at_us(0));
  bus.send(ea, CanFrame::data_frame(0x182, {1, 2}), at_us(0));
  std::int64_t t = 0;
  while (bus.counters(ea).state != ErrorState::BusOff && t < 20000) bus.deliver(at_us(t += 10));
  ASSERT_EQ(bus.counters(ea).state, ErrorState::BusOff);
  EXPECT_EQ(bus.counters(ea).bus_off_events, 1u);
  EXPECT_EQ(bus.stats().error_frames, 32u);
  EXPECT_EQ(bus.pending_frames(), 0u);  // flushed
  ASSERT_EQ(a.states.size(), 2u);
  EXPECT_EQ(a.states[1], ErrorState::BusOff);
  // Bus-off: b's frames do not reach a.
  bus.send(eb, CanFrame::data_frame(0x201, {}), at_us(t));
  bus.send(ea, CanFrame::data_frame(0x183, {}), at_us(t));
  bus.deliver(at_us(t + 200));
  EXPECT_TRUE(a.frames.empty());
  EXPECT_EQ(b.frames.size(), 0u);
  EXPECT_EQ(bus.pending_frames(), 0u);
  EXPECT_EQ(a.states.size(), 2u);
  // 128 * 11 bits at 2 us = 2816 us of recessive bus after the bus-off.
  bus.deliver(at_us(20000));
  ASSERT_EQ(a.states.size(), 3u);
  EXPECT_EQ(a.states[2], ErrorState::Active);
  EXPECT_EQ(bus.counters(ea).tec, 0u);
  errors.count = 0;
  bus.send(ea, CanFrame::data_frame(0x184, {}), at_us(20000));
  bus.deliver(at_us(21000));
  ASSERT_FALSE(b.frames.empty());
  EXPECT_EQ(b.frames.back().id, 0x184u);
}

TEST(BusTiming, BusOffRecoveryNeeds128Sequences) {
  Bus bus("main");
  bus.set_timing(BusTiming::Bit, 500000);
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  BitErrors errors;
  errors.endpoint = ea;
  errors.count = 32;
  bus.set_filter(&errors);
  bus.send(ea, CanFrame::data_frame(0x181, {}), at_us(0));
  // Every attempt: the frame's stuffed region + 3 + 23 error-frame bits at 2 us.
  std::int64_t t = 0;
  while (bus.counters(ea).state != ErrorState::BusOff) {
    t += 100;
    bus.deliver(at_us(t));
  }
  const std::int64_t off = t;
  // Recovery cannot come before 128 * 11 bit times (2816 us) of recessive bus.
  bus.deliver(at_us(off + 2816 - 200));
  EXPECT_EQ(bus.counters(ea).state, ErrorState::BusOff);
  bus.deliver(at_us(off + 2816 + 200));
  EXPECT_EQ(bus.counters(ea).state, ErrorState::Active);
}

TEST(BusTiming, ErrorsOnTheIdealBusCountToo) {
  Bus bus("main");
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  BitErrors errors;
  errors.endpoint = ea;
  errors.count = 20;
  bus.set_filter(&errors);
  bus.send(ea, CanFrame::data_frame(0x181, {}), at_us(0));
  bus.deliver(at_us(0));
  EXPECT_EQ(b.frames.size(), 1u);
  EXPECT_EQ(bus.counters(ea).tec, 159u);
  EXPECT_EQ(bus.counters(ea).state, ErrorState::Passive);
}
