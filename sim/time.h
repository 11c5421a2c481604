// Simulation time: one clock type shared by the scheduler, buses, nodes and the plant.
#pragma once

#include <chrono>
#include <cstdint>

namespace sim {

/// Microseconds since the start of a run. Virtual time advances tick by tick; real time maps
/// CLOCK_MONOTONIC onto the same axis, so device code never knows which clock drives it.
struct SimClock {
  using rep = std::int64_t;
  using period = std::micro;
  using duration = std::chrono::microseconds;
  using time_point = std::chrono::time_point<SimClock>;
  static constexpr bool is_steady = true;
};

using Duration = SimClock::duration;
using Time = SimClock::time_point;

inline constexpr Time kTimeZero{};

constexpr Duration milliseconds(std::int64_t ms) { return Duration{ms * 1000}; }
constexpr Duration microseconds(std::int64_t us) { return Duration{us}; }
constexpr double seconds(Duration d) { return static_cast<double>(d.count()) * 1e-6; }
constexpr double seconds(Time t) { return seconds(t.time_since_epoch()); }
inline Duration from_seconds(double s) { return Duration{static_cast<std::int64_t>(s * 1e6 + (s >= 0 ? 0.5 : -0.5))}; }

}  // namespace sim
