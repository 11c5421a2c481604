// Helpers for the plant tests: stepping a plant through simulated time and reading its ports.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "plant/plant.h"

namespace plant::testing {

/// Steps `p` by `seconds` of simulated time in ticks of `tick`; `each_tick(t)` runs before each
/// tick with the time since this call began (inputs are written there, as a device would).
template <typename F>
void run(Plant& p, double seconds, F&& each_tick, sim::Duration tick = sim::milliseconds(1)) {
  sim::Time now{};
  const auto n = static_cast<long>(std::llround(seconds / sim::seconds(tick)));
  for (long k = 0; k < n; ++k) {
    each_tick(sim::seconds(now));
    p.step(now, tick);
    now += tick;
  }
}
inline void run(Plant& p, double seconds, sim::Duration tick = sim::milliseconds(1)) {
  run(p, seconds, [](double) {}, tick);
}

/// A port's value; fails the test when the port does not exist.
inline double& port(const Plant& p, const std::string& name) {
  double* v = p.port(name);
  if (v == nullptr) {
    ADD_FAILURE() << "no port " << name;
    static double dummy = 0.0;
    return dummy;
  }
  return *v;
}

inline double relative_error(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

/// A measured figure for the test report (RecordProperty), in scientific notation.
inline std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3e", value);
  return text;
}

constexpr double kBar = 1e5;
constexpr double kLitresPerMinute = 1e-3 / 60.0;

}  // namespace plant::testing
