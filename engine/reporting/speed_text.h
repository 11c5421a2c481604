// How fast a run went, for people: "0.6× real time", "12× real time". One decimal below 10×, so a
// run slower than the wall clock never reads "1× real time".
#pragma once

#include <cstdio>
#include <string>

namespace scenario {

inline std::string real_time_factor_text(double simulated_s, double wall_s) {
  if (!(wall_s > 0)) return "no wall time elapsed";
  const double factor = simulated_s / wall_s;
  char buf[48];
  std::snprintf(buf, sizeof buf, factor < 9.95 ? "%.1f× real time" : "%.0f× real time", factor);
  return buf;
}

}  // namespace scenario
