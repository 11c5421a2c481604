#include "sim/scheduler.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using sim::CanFrame;
using sim::Duration;
using sim::Time;

struct Logger : sim::Steppable {
  Logger(std::vector<std::pair<char, std::int64_t>>* l, char t) : log(l), tag(t) {}
  std::vector<std::pair<char, std::int64_t>>* log;
  char tag;
  void step(Time now, Duration) override { log->push_back({tag, now.time_since_epoch().count()}); }
};

}  // namespace

TEST(Scheduler, VirtualTicksRunInOrderAndAdvanceTime) {
  std::vector<std::pair<char, std::int64_t>> log;
  Logger a(&log, 'a'), b(&log, 'b');
  sim::Scheduler s(sim::milliseconds(1));
  s.add(&a);
  s.add(&b);
  s.run_ticks(3);
  ASSERT_EQ(log.size(), 6u);
  EXPECT_EQ(log[0], (std::pair<char, std::int64_t>{'a', 0}));
  EXPECT_EQ(log[1], (std::pair<char, std::int64_t>{'b', 0}));
  EXPECT_EQ(log[5], (std::pair<char, std::int64_t>{'b', 2000}));
  EXPECT_EQ(s.now().time_since_epoch().count(), 3000);
  EXPECT_EQ(s.stats().ticks, 3u);
}

TEST(Scheduler, RunForRoundsUpToWholeTicks) {
  sim::Scheduler s(sim::milliseconds(2));
  s.run_for(sim::milliseconds(5));
  EXPECT_EQ(s.now().time_since_epoch().count(), 6000);
}

TEST(Scheduler, FrameSentInATickReachesLaterComponentsInTheSameTick) {
  sim::Bus bus("main");
  struct Sender : sim::Steppable, sim::FrameReceiver {
    sim::Bus* bus;
    int ep;
    void step(Time now, Duration) override { bus->send(ep, CanFrame::data_frame(0x100, {}), now); }
    void on_frame(const CanFrame&, Time) override {}
  } sender;
  struct Receiver : sim::Steppable, sim::FrameReceiver {
    int frames_before_step = 0;
    int received = 0;
    void step(Time, Duration) override { frames_before_step = received; }
    void on_frame(const CanFrame&, Time) override { ++received; }
  } receiver;
  sender.bus = &bus;
  sender.ep = bus.attach(&sender);
  bus.attach(&receiver);
  sim::Scheduler s;
  s.add_bus(&bus);
  s.add(&sender);
  s.add(&receiver);
  s.run_ticks(1);
  EXPECT_EQ(receiver.frames_before_step, 1);
}

TEST(Scheduler, RealTimeKeepsPaceAndStops) {
  // Coarse check only (the machine may be loaded): 20 ticks of 1 ms cannot finish in < 19 ms.
  sim::Scheduler s(sim::milliseconds(1), sim::ClockMode::RealTime);
  timespec t0{}, t1{};
  clock_gettime(CLOCK_MONOTONIC, &t0);
  s.run_ticks(20);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  const double elapsed_ms = (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) / 1e6;
  EXPECT_GE(elapsed_ms, 18.9);
  EXPECT_EQ(s.stats().ticks, 20u);
  s.request_stop();
  s.run_ticks(5);
  EXPECT_EQ(s.stats().ticks, 20u);
}
