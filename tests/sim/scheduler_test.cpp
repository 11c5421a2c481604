#include "sim/scheduler.h"

#include <gtest/gtest.h>
#include <linux/can.h>
#include <sys/socket.h>
#include <unistd.h>

#include <thread>
#include <vector>

#include "sim/bus.h"
#include "sim/socketcan_transport.h"

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

namespace {
// Sleeps through one chosen tick, as an overloaded component would.
struct Stall : sim::Steppable {
  std::uint64_t ticks = 0, stall_at = 0;
  std::chrono::milliseconds length{0};
  void step(Time, Duration) override {
    if (ticks++ == stall_at) std::this_thread::sleep_for(length);
  }
};

struct TickCounter : sim::Steppable {
  std::uint64_t ticks = 0;
  void step(Time, Duration) override { ++ticks; }
};

// Records, for each frame, how many ticks had run when it was handled.
struct ArrivalLog : sim::FrameReceiver {
  const TickCounter* counter = nullptr;
  std::vector<std::uint64_t> at_tick;
  void on_frame(const CanFrame&, Time) override { at_tick.push_back(counter->ticks); }
};
}  // namespace

TEST(Scheduler, RealTimeCountsOverrunsAndLateness) {
  // A 6 ms stall in a 1 ms tick: the next tick starts at least 5 ms after its deadline, however
  // fast or slow the machine is.
  sim::Scheduler s(sim::milliseconds(1), sim::ClockMode::RealTime);
  Stall stall;
  stall.stall_at = 3;
  stall.length = std::chrono::milliseconds(6);
  s.add(&stall);
  s.run_ticks(10);
  EXPECT_GE(s.stats().overruns, 1u);
  EXPECT_GE(s.stats().max_lateness, sim::milliseconds(5));
  EXPECT_EQ(s.stats().ticks, 10u);
}

namespace {
// The CLOCK_MONOTONIC time at which each tick ran.
struct TickTimes : sim::Steppable {
  std::vector<double> ms;
  void step(Time, Duration) override {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    ms.push_back(static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6);
  }
};
}  // namespace

TEST(Scheduler, RealTimeReanchorsAfterAStallInsteadOfBursting) {
  // A 6 ms stall in tick 3 of 1 ms ticks. The missed ticks are not run back to back: tick 4
  // starts the schedule anew, so ticks 5..11 wait for deadlines 1..7 ms after it (a loaded machine
  // can only make them later; caught up, ticks 4..9 would run back to back and tick 11 would come
  // about 2 ms after tick 4), and simulated time pauses for the stall instead of jumping.
  sim::Scheduler s(sim::milliseconds(1), sim::ClockMode::RealTime);
  Stall stall;
  stall.stall_at = 3;
  stall.length = std::chrono::milliseconds(6);
  TickTimes times;
  s.add(&stall);
  s.add(&times);
  s.run_ticks(12);
  ASSERT_EQ(times.ms.size(), 12u);
  EXPECT_GE(times.ms[11] - times.ms[4], 6.9);
  EXPECT_GE(s.stats().reanchors, 1u);
  EXPECT_GE(s.stats().slipped, sim::milliseconds(5));
  EXPECT_EQ(s.now(), Time{sim::milliseconds(12)});
}

TEST(Scheduler, VirtualTimeNeverReanchors) {
  sim::Scheduler s(sim::milliseconds(1), sim::ClockMode::Virtual);
  Stall stall;
  stall.length = std::chrono::milliseconds(3);
  s.add(&stall);
  s.run_ticks(5);
  EXPECT_EQ(s.stats().reanchors, 0u);
  EXPECT_EQ(s.stats().slipped, Duration{0});
  EXPECT_EQ(s.stats().overruns, 0u);
}

TEST(Scheduler, RealTimeHandlesAFrameWhenItArrivesNotAtTheNextTick) {
  // A socketpair stands in for a CAN socket (same record format). Ticks are 300 ms long; the
  // frame is written 30 ms into the first tick's wait and must be handled before tick 2 starts.
  int fds[2];
  ASSERT_EQ(socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_NONBLOCK, 0, fds), 0);
  sim::Bus bus("main");
  bus.set_transport(sim::SocketCanTransport::adopt("pair0", fds[0]));
  TickCounter counter;
  ArrivalLog log;
  log.counter = &counter;
  bus.attach(&log);
  sim::Scheduler s(sim::milliseconds(300), sim::ClockMode::RealTime);
  s.add_bus(&bus);
  s.add(&counter);
  std::thread peer([fd = fds[1]] {
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    can_frame raw{};
    raw.can_id = 0x605;
    raw.can_dlc = 1;
    EXPECT_EQ(write(fd, &raw, sizeof raw), static_cast<ssize_t>(sizeof raw));
  });
  s.run_ticks(2);
  peer.join();
  close(fds[1]);
  EXPECT_EQ(log.at_tick, std::vector<std::uint64_t>{1});  // after tick 1's step, before tick 2's
  EXPECT_EQ(s.stats().frames_between_ticks, 1u);
}
