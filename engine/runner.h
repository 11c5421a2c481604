// Runs a scenario: builds the world, the fault injector, the scripted master and the recorder,
// puts them on one scheduler in this order per tick
//   1 fault injector    faults due at `now` act before anything else sees the tick
//   2 scripted master   decides assertions on the state at `now`, sends SYNC/NMT/SDO/PDOs
//   3 plant → devices   sensor inputs = plant outputs at `now`
//   4 nodes             (scenario order) consume the tick's frames, sample inputs, drive outputs
//     master monitor    the verdict on the master: SDO timeouts, device states (master_monitor.h)
//   5 devices → plant   actuator commands for [now, now + dt]
//   6 recorder          CSV/report row: plant state at `now`, device outputs for the tick
//   7 plant             integrates [now, now + dt]
// (the buses deliver after every component, so a request and its answer share a tick), runs it
// until its duration, the end of the script, or SIGINT, and writes the outputs and the summary.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/running/environment.h"
#include "engine/running/outcome.h"
#include "engine/running/run_extension.h"
#include "engine/running/run_summary.h"
#include "engine/loading/scenario.h"

namespace sim {
class Scheduler;
}

namespace scenario {

class MasterMonitor;

struct RunOptions {
  std::map<std::string, std::string> can;  ///< --can BUS=IFACE
  bool realtime = false;                   ///< --realtime
  bool no_script = false;                  ///< --no-script: drop the script and clock.duration (an external master drives)
  std::optional<sim::Duration> duration;   ///< --duration
  std::optional<std::uint64_t> seed;       ///< --seed
  std::string trace, csv, junit;           ///< override the scenario's outputs
  std::string report_dir;                  ///< --report DIR: write this case into the HTML report (engine/reporting/html/)
  std::string master_report;               ///< --master-report: the master monitor's findings as JSON
  bool progress = false;                   ///< progress line on stderr (a terminal)
  bool quiet = false;                      ///< no summary (tests, benchmarks)
  bool strict_eds = false;                 ///< --strict: EDS nodes reject CiA 306 deviations
  /// --power-on-first-client: the nodes of a bus served over socketcand stay unpowered until its
  /// first client is in raw mode, so an external master sees every boot-up.
  bool power_on_first_client = false;
  bool rt = false;                         ///< --rt: SCHED_FIFO + locked memory for the scheduler's thread (sim/realtime_setup.h)
  std::FILE* out = stderr;                 ///< summary, failures, log lines
  /// run_scenario_file: only this case of the file's matrix (`vplant run --case`); "" = all.
  std::string case_name;
  /// Watches and steers the run between ticks (the live control plane); may keep a run going
  /// past its duration. Not owned.
  RunExtension* extension = nullptr;
  /// Or: makes the extension once the scenario is loaded (from its `ui:`); nullptr = none.
  /// Throws LoadError for a bad `ui:` (e.g. a port in use).
  std::function<RunExtension*(const Scenario&)> extension_for;
};

class Runner {
 public:
  /// Builds everything; throws LoadError for a scenario that cannot run.
  Runner(const Scenario& scenario, const Environment& env, const RunOptions& options);
  ~Runner();
  Runner(const Runner&) = delete;
  Runner& operator=(const Runner&) = delete;

  /// Runs to the end and writes the outputs. Returns the exit code: 0 all assertions held,
  /// 1 one failed, 2 an output could not be written. An extension that asks for a restart
  /// (RunExtension::wants_restart) has the run rebuilt and started again at t = 0.
  int run();
  /// Async-signal-safe: ends the run at the next tick boundary.
  void request_stop();

  const Verdicts& verdicts() const;
  const RunSummary& summary() const;
  /// The verdict on the master: the findings of the master monitor (master_monitor.h).
  const MasterMonitor& master_monitor() const;

 private:
  struct Impl;
  /// Builds the run from the scenario (the constructor, and again for a restart).
  void build();
  /// One run from t = 0; `restarted` when the extension asked for a restart (nothing written).
  int run_once(bool& restarted);
  /// Drops the run and builds it afresh (the old one first: its sockets and files are freed).
  void rebuild();
  const Environment env_;  ///< a copy: a rebuild outlives the caller's
  std::unique_ptr<Impl> impl_;
  std::atomic<bool> stopping_{false};
  std::atomic<sim::Scheduler*> scheduler_{nullptr};  ///< request_stop's, null while rebuilding
};

/// Loads and runs a scenario file, each case of its matrix in turn (scenario_cases.h): the whole
/// of `vplant run` after option parsing. Prints errors as `file:line:col: reason`; returns 0, 1
/// or 2 (the worst of the cases).
int run_scenario_file(const std::string& path, const Environment& env, const RunOptions& options);

/// The runner currently executing (for a SIGINT handler), or nullptr.
Runner* active_runner();

}  // namespace scenario
