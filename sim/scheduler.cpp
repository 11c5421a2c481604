#include "sim/scheduler.h"

#include <signal.h>
#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <limits>

#include "sim/tick_profile.h"

namespace sim {

Scheduler::Scheduler(Duration tick, ClockMode mode) : tick_(tick), mode_(mode) {
  if (tick_.count() <= 0) tick_ = milliseconds(1);
}

std::int64_t Scheduler::monotonic_ns() const {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

void Scheduler::deliver_pending() {
  const TickProbe probe(TickPart::Bus);
  // Deliver until quiet across buses: a gateway-like component may forward between buses.
  for (int round = 0; round < 8; ++round) {
    std::size_t n = 0;
    for (auto* bus : buses_) n += bus->deliver(now_);
    if (n == 0) break;
  }
}

void Scheduler::run_tick() {
  for (auto* bus : buses_) bus->poll_transport(now_);
  deliver_all();
  for (auto* c : components_) {
    c->step(now_, tick_);
    deliver_all();
  }
  ++stats_.ticks;
  now_ += tick_;
}

void Scheduler::run_ticks(std::uint64_t n) { run(n); }

void Scheduler::run_for(Duration d) {
  if (d.count() <= 0) return;
  const auto n = static_cast<std::uint64_t>((d.count() + tick_.count() - 1) / tick_.count());
  run(n);
}

void Scheduler::run_until_stopped() { run(std::numeric_limits<std::uint64_t>::max()); }

void Scheduler::run(std::uint64_t max_ticks) {
  if (mode_ == ClockMode::Virtual) {
    for (std::uint64_t i = 0; i < max_ticks && !stop_requested(); ++i) run_tick();
    return;
  }
  if (!rt_started_) {
    // The kernel's default 50 us timer slack would delay every wake-up from ppoll(); ask for the
    // minimum (per thread, unprivileged).
    ::prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    // Real time starts where simulated time stands, so ticks keep their absolute schedule.
    rt_start_ns_ = monotonic_ns() - now_.time_since_epoch().count() * 1000;
    rt_started_ = true;
  }
  const std::int64_t tick_ns = tick_.count() * 1000;
  for (std::uint64_t i = 0; i < max_ticks && !stop_requested(); ++i) {
    const std::int64_t deadline = rt_start_ns_ + now_.time_since_epoch().count() * 1000;
    wait_for_deadline(deadline);
    if (stop_requested()) break;
    const std::int64_t late_ns = monotonic_ns() - deadline;
    const Duration late{late_ns / 1000};
    if (late > stats_.max_lateness) stats_.max_lateness = late;
    if (lateness_observer_) lateness_observer_(late);
    if (late_ns > tick_ns) {
      // Catch-up policy (scheduler.h): this tick starts the schedule anew; the missed ticks are
      // not run back to back, simulated time pauses for the stall.
      ++stats_.overruns;
      ++stats_.reanchors;
      rt_start_ns_ += late_ns;
      stats_.slipped += late;
    }
    run_tick();
  }
}

void Scheduler::wait_for_deadline(std::int64_t deadline_ns) {
  for (;;) {
    const std::int64_t now_ns = monotonic_ns();
    if (now_ns >= deadline_ns || stop_requested()) return;
    pollfds_.clear();
    pollfd_bus_.clear();
    for (auto* bus : buses_) {
      if (bus->transport() && bus->transport()->wait_fd() >= 0) {
        pollfds_.push_back(pollfd{bus->transport()->wait_fd(), POLLIN, 0});
        pollfd_bus_.push_back(bus);
      }
    }
    const std::int64_t wait_ns = deadline_ns - now_ns;
    timespec timeout{static_cast<time_t>(wait_ns / 1000000000LL), static_cast<long>(wait_ns % 1000000000LL)};
    const int rc = ::ppoll(pollfds_.data(), pollfds_.size(), &timeout, nullptr);
    if (rc <= 0) continue;  // timeout, EINTR: re-check the deadline and the stop flag
    // A frame arrived between ticks: handle it now, stamped with the current real time (kept
    // inside the current tick interval so components always see monotonic time).
    const Time tick_start = now_ - tick_;
    Time arrival{Duration{(monotonic_ns() - rt_start_ns_) / 1000}};
    arrival = std::clamp(arrival, tick_start, now_);
    const Time saved = now_;
    now_ = arrival;
    for (std::size_t i = 0; i < pollfds_.size(); ++i) {
      if (pollfds_[i].revents & (POLLIN | POLLERR)) stats_.frames_between_ticks += pollfd_bus_[i]->poll_transport(now_);
    }
    deliver_all();
    now_ = saved;
  }
}

}  // namespace sim
