#include "sim/bus.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using sim::CanFrame;
using sim::Time;

struct Recorder : sim::FrameReceiver {
  std::vector<CanFrame> frames;
  void on_frame(const CanFrame& f, Time) override { frames.push_back(f); }
};

// Answers every frame with id 0x600+n by a frame 0x580+n, like an SDO server would.
struct Echo : sim::FrameReceiver {
  sim::Bus* bus = nullptr;
  int me = -1;
  void on_frame(const CanFrame& f, Time now) override {
    if (f.id >= 0x600 && f.id < 0x680) bus->send(me, CanFrame::data_frame(f.id - 0x80, {0x60}), now);
  }
};

}  // namespace

TEST(Bus, DeliversToAllOtherEndpointsButNotTheSender) {
  sim::Bus bus("main");
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  bus.send(ea, CanFrame::data_frame(0x181, {1}), Time{});
  EXPECT_EQ(bus.deliver(Time{}), 1u);
  EXPECT_TRUE(a.frames.empty());
  ASSERT_EQ(b.frames.size(), 1u);
  EXPECT_EQ(b.frames[0].id, 0x181u);
}

TEST(Bus, RepliesAreDeliveredInTheSameCall) {
  sim::Bus bus("main");
  Recorder master;
  Echo node;
  const int em = bus.attach(&master);
  node.bus = &bus;
  node.me = bus.attach(&node);
  bus.send(em, CanFrame::data_frame(0x605, {0x40}), Time{});
  EXPECT_EQ(bus.deliver(Time{}), 2u);
  ASSERT_EQ(master.frames.size(), 1u);
  EXPECT_EQ(master.frames[0].id, 0x585u);
}

TEST(Bus, OfflineEndpointNeitherSendsNorReceives) {
  sim::Bus bus("main");
  Recorder a, b;
  const int ea = bus.attach(&a);
  const int eb = bus.attach(&b);
  bus.set_online(eb, false);
  bus.send(ea, CanFrame::data_frame(0x181, {1}), Time{});
  bus.send(eb, CanFrame::data_frame(0x182, {1}), Time{});
  bus.deliver(Time{});
  EXPECT_TRUE(a.frames.empty());
  EXPECT_TRUE(b.frames.empty());
}

// Receivers are called in endpoint order; one that takes a later endpoint off the bus while a
// frame is being delivered keeps the frame from it, one that brings it back lets it through.
TEST(Bus, AReceiverChangingAnotherEndpointsStateMidDeliveryIsHonoured) {
  struct Switcher : sim::FrameReceiver {
    sim::Bus* bus = nullptr;
    int other = -1;
    bool online = false;
    void on_frame(const CanFrame&, Time) override { bus->set_online(other, online); }
  };
  for (const auto timing : {sim::BusTiming::Ideal, sim::BusTiming::Bit}) {
    sim::Bus bus("main");
    bus.set_timing(timing);
    Recorder a, c, d;
    Switcher b;
    const int ea = bus.attach(&a);
    bus.attach(&b);
    const int ec = bus.attach(&c);
    bus.attach(&d);
    b.bus = &bus;
    b.other = ec;
    bus.send(ea, CanFrame::data_frame(0x181, {1}), Time{});
    bus.deliver(Time{} + sim::milliseconds(1));
    EXPECT_TRUE(c.frames.empty());
    EXPECT_EQ(d.frames.size(), 1u);
    b.online = true;
    bus.send(ea, CanFrame::data_frame(0x181, {2}), Time{} + sim::milliseconds(1));
    bus.deliver(Time{} + sim::milliseconds(2));
    ASSERT_EQ(c.frames.size(), 1u);
    EXPECT_EQ(c.frames[0].data[0], 2);
    EXPECT_EQ(d.frames.size(), 2u);
  }
}

// deliver() remembers an instant it found nothing to do at; a frame sent afterwards at that
// instant is still delivered (ideal timing: by the next deliver() at the same instant).
TEST(Bus, SettledBusStillDeliversWhatIsSentLater) {
  sim::Bus bus("main");
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  const Time t = Time{} + sim::milliseconds(3);
  EXPECT_EQ(bus.deliver(t), 0u);  // time moved: the bus catches up (idle time)
  EXPECT_FALSE(bus.settled(t));
  EXPECT_EQ(bus.deliver(t), 0u);  // nothing left at t
  EXPECT_TRUE(bus.settled(t));
  bus.send(ea, CanFrame::data_frame(0x181, {1}), t);
  EXPECT_FALSE(bus.settled(t));
  EXPECT_EQ(bus.deliver(t), 1u);
  EXPECT_EQ(b.frames.size(), 1u);
  EXPECT_EQ(bus.deliver(t), 0u);
  EXPECT_TRUE(bus.settled(t));
  EXPECT_FALSE(bus.settled(t + sim::microseconds(1)));
}

TEST(Bus, FilterCanDropAndDelay) {
  struct DropAndDelay : sim::FrameFilter {
    Verdict on_send(CanFrame& f, int, Time) override {
      if (f.id == 0x181) return {true, {}};
      if (f.id == 0x182) return {false, sim::milliseconds(5)};
      return {};
    }
  } filter;
  sim::Bus bus("main");
  Recorder a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  bus.set_filter(&filter);
  bus.send(ea, CanFrame::data_frame(0x181, {1}), Time{});
  bus.send(ea, CanFrame::data_frame(0x182, {1}), Time{});
  bus.send(ea, CanFrame::data_frame(0x183, {1}), Time{});
  bus.deliver(Time{});
  ASSERT_EQ(b.frames.size(), 1u);
  EXPECT_EQ(b.frames[0].id, 0x183u);
  bus.deliver(Time{} + sim::milliseconds(4));
  EXPECT_EQ(b.frames.size(), 1u);
  bus.deliver(Time{} + sim::milliseconds(5));
  ASSERT_EQ(b.frames.size(), 2u);
  EXPECT_EQ(b.frames[1].id, 0x182u);
  EXPECT_EQ(bus.stats().dropped_by_filter, 1u);
}

TEST(Bus, TapSeesEveryFrameOnce) {
  struct Count : sim::FrameTap {
    int n = 0;
    std::string name;
    void on_bus_frame(std::string_view wire, const CanFrame&, Time) override {
      ++n;
      name = wire;
    }
  } tap;
  sim::Bus bus("main");
  Recorder a, b, c;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  bus.attach(&c);
  bus.add_tap(&tap);
  bus.send(ea, CanFrame::data_frame(0x181, {1}), Time{});
  bus.deliver(Time{});
  EXPECT_EQ(tap.n, 1);
  EXPECT_EQ(tap.name, "main");
}
