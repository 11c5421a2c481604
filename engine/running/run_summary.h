// What one run measured: simulated and wall time, ticks and their lateness, each bus's frames and
// load, the verdicts' counts. The runner fills it; the summary lines and the HTML report read it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace scenario {

struct RunSummary {
  double simulated_s = 0;
  double wall_s = 0;
  std::uint64_t ticks = 0;
  bool realtime = false;
  std::uint64_t overruns = 0;
  std::int64_t max_lateness_us = 0;
  std::uint64_t reanchors = 0;   ///< overruns after which the schedule was re-anchored (sim/scheduler.h)
  std::int64_t slipped_us = 0;   ///< how far simulated time lags the wall clock after them
  struct BusFrames {
    std::string name, wire;
    std::uint64_t frames = 0;
    std::string load;  ///< timing, load, load per COB-ID (engine/reporting/bus_report.h)
    std::uint64_t busy_bits = 0;  ///< bits the frames and error frames occupied
    std::uint32_t bit_rate = 0;   ///< the rate the bus was timed at
  };
  std::vector<BusFrames> buses;
  std::size_t assertions = 0;
  std::size_t failures = 0;
  std::size_t faults = 0;
  std::size_t master_findings = 0;        ///< the master monitor's findings (all rules, dropped ones too)
  std::size_t master_errors = 0;          ///< of which of error severity
  bool interrupted = false;
};

}  // namespace scenario
