// The one clock of a run. Each tick: frames that arrived are delivered, then every component
// steps in the order it was added (nodes, plant, recorders), with bus delivery after each, so a
// frame sent in a tick reaches its receivers in the same tick.
//
// Virtual time runs ticks back to back (deterministic, as fast as possible). Real time paces
// ticks by absolute deadlines on CLOCK_MONOTONIC; between ticks it waits in ppoll() on the
// transports' sockets, so a received frame is handled when it arrives, not at the next tick.
//
// Catch-up policy (real time): a tick that starts more than one tick late (an overrun: the
// machine stalled the process) re-anchors the schedule at that moment instead of running the
// missed ticks back to back. Simulated time does not jump: it pauses for the stall and from then
// on lags the wall clock by the time lost (SchedulerStats::slipped), so every period the nodes
// keep in simulated time (heartbeats, SYNC, event timers) stays one period apart on the wire too,
// except the one period the stall itself stretched. A late start within one tick is absorbed by
// the absolute deadlines as before.
#pragma once

#include <poll.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "sim/bus.h"
#include "sim/time.h"

namespace sim {

/// A component that advances with the scheduler. `now` is the start of the tick; a component
/// processes everything due at or before `now` and integrates continuous state over [now, now+dt].
class Steppable {
 public:
  virtual ~Steppable() = default;
  virtual void step(Time now, Duration dt) = 0;
};

enum class ClockMode { Virtual, RealTime };

struct SchedulerStats {
  std::uint64_t ticks = 0;
  std::uint64_t overruns = 0;        ///< real time: ticks that started after the next deadline
  Duration max_lateness{0};          ///< real time: worst tick start after its deadline
  std::uint64_t frames_between_ticks = 0;  ///< real time: frames handled on arrival
  std::uint64_t reanchors = 0;       ///< real time: overruns after which the schedule was re-anchored
  Duration slipped{0};               ///< real time: how far simulated time lags the wall clock (stalls)
};

class Scheduler {
 public:
  explicit Scheduler(Duration tick = milliseconds(1), ClockMode mode = ClockMode::Virtual);

  void add_bus(Bus* bus) { buses_.push_back(bus); }
  void add(Steppable* component) { components_.push_back(component); }

  Duration tick() const { return tick_; }
  ClockMode mode() const { return mode_; }
  Time now() const { return now_; }
  const SchedulerStats& stats() const { return stats_; }

  /// Runs exactly `n` ticks.
  void run_ticks(std::uint64_t n);
  /// Runs until simulated time has advanced by `d` (or stop was requested).
  void run_for(Duration d);
  /// Runs until request_stop() (real time: typically from a signal handler).
  void run_until_stopped();
  /// Async-signal-safe.
  void request_stop() { stop_.store(true, std::memory_order_relaxed); }
  bool stop_requested() const { return stop_.load(std::memory_order_relaxed); }

  /// Called with each real-time tick's lateness (for benchmarks); must not allocate.
  void set_lateness_observer(std::function<void(Duration)> observer) { lateness_observer_ = std::move(observer); }

  /// Delivers pending frames on all buses at the current time (used by tests between ticks).
  /// Called after every component: when every bus is settled at now (nothing sent since it last
  /// found nothing to do) it is a compare per bus.
  void deliver_all() {
    for (auto* bus : buses_) {
      if (!bus->settled(now_)) {
        deliver_pending();
        return;
      }
    }
  }

 private:
  void run_tick();
  void deliver_pending();
  void run(std::uint64_t max_ticks);
  void wait_for_deadline(std::int64_t deadline_ns);
  std::int64_t monotonic_ns() const;

  Duration tick_;
  ClockMode mode_;
  Time now_{};
  std::vector<Bus*> buses_;
  std::vector<Steppable*> components_;
  std::vector<pollfd> pollfds_;
  std::vector<Bus*> pollfd_bus_;
  std::atomic<bool> stop_{false};
  SchedulerStats stats_;
  std::function<void(Duration)> lateness_observer_;
  std::int64_t rt_start_ns_ = 0;  // CLOCK_MONOTONIC at the first real-time tick
  bool rt_started_ = false;
};

}  // namespace sim
