// `vplant run SCENARIO`: the whole plant from a scenario file (docs/scenarios.md). Exit codes:
// 0 every assertion held, 1 one failed, 2 bad input (file, option, interface).
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "control/control_plane.h"
#include "engine/reporting/html/report_writer.h"
#include "engine/runner.h"
#include "engine/loading/yaml_fields.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exercise_folder.h"
#include "tools/vplant/exit_codes.h"
#include "tools/vplant/key_value.h"
#include "tools/vplant/stop_signals.h"

namespace vplant {

namespace {

struct RunArgs {
  std::string scenario;
  std::vector<std::string> can;
  bool realtime = false;
  bool no_script = false;
  std::string duration;
  long long seed = -1;
  std::string trace, csv, junit;
  std::string master_report;
  bool quiet = false;
  std::string ui;
  bool ui_allow_remote = false;
  bool ui_run = false;
  double ui_speed = -1;
  bool strict = false;
  std::string case_name;
  std::string report;
  bool report_no_index = false;
  bool rt = false;
  bool power_on_first_client = false;
  std::string exercises;  ///< "" = the shipped folder
  std::string exercise;
};

bool stop_active_run() {
  auto* r = scenario::active_runner();
  if (!r) return false;
  r->request_stop();
  return true;
}

int run(const RunArgs& a) {
  install_stop_signals(stop_active_run);
  scenario::RunOptions o;
  std::string error;
  if (!parse_key_values(a.can, o.can, error)) {
    std::fprintf(stderr, "vplant run: --can %s (expected BUS=IFACE)\n", error.c_str());
    return kExitBadInput;
  }
  if (!a.duration.empty()) {
    std::string problem;
    const auto d = scenario::parse_duration(a.duration, &problem);
    if (!d || d->count() <= 0) {
      if (d) problem = "is not positive";
      std::fprintf(stderr, "vplant run: --duration '%s' %s\n", a.duration.c_str(), problem.c_str());
      return kExitBadInput;
    }
    o.duration = *d;
  }
  if (a.seed >= 0) o.seed = static_cast<std::uint64_t>(a.seed);
  o.realtime = a.realtime;
  o.no_script = a.no_script;
  o.trace = a.trace;
  o.csv = a.csv;
  o.junit = a.junit;
  o.master_report = a.master_report;
  o.quiet = a.quiet;
  o.strict_eds = a.strict;
  o.case_name = a.case_name;
  o.report_dir = a.report;
  o.rt = a.rt;
  o.power_on_first_client = a.power_on_first_client;
  o.progress = !a.quiet && ::isatty(STDERR_FILENO);
  // The control plane: --ui overrides the scenario's `ui:`; made once the scenario is loaded.
  std::unique_ptr<control::ControlPlane> ui;
  if (!a.exercise.empty() && a.ui.empty()) {
    std::fprintf(stderr, "vplant run: --exercise needs --ui (the page shows it)\n");
    return kExitBadInput;
  }
  if (!a.ui.empty()) {
    control::UiOptions probe;
    if (auto err = control::parse_ui_address(a.ui, probe); !err.empty()) {
      std::fprintf(stderr, "vplant run: --ui %s\n", err.c_str());
      return kExitBadInput;
    }
  }
  o.extension_for = [&a, &ui](const scenario::Scenario& s) -> scenario::RunExtension* {
    const std::string listen = !a.ui.empty() ? a.ui : s.ui.listen;
    if (listen.empty()) return nullptr;
    const scenario::SourceMark mark = !a.ui.empty() ? scenario::SourceMark{"--ui", 0, 0} : s.ui.mark;
    control::UiOptions u;
    if (auto err = control::parse_ui_address(listen, u); !err.empty()) throw scenario::LoadError(mark, "ui: " + err);
    u.allow_remote = a.ui_allow_remote || (a.ui.empty() && s.ui.allow_remote);
    u.clock.start_paused = a.ui_run ? false : s.ui.start_paused;
    u.clock.speed = a.ui_speed >= 0 ? a.ui_speed : s.ui.speed;
    u.exercises_dir = a.exercises.empty() ? default_exercises_dir() : a.exercises;
    u.exercise = a.exercise;
    ui = std::make_unique<control::ControlPlane>(u);
    if (auto err = ui->bind(); !err.empty()) throw scenario::LoadError(mark, err);
    return ui.get();
  };
  int rc = scenario::run_scenario_file(a.scenario, scenario::default_environment(), o);
  // The index lists every case in the folder (`vplant test` writes it once, after all its cases).
  if (!a.report.empty() && !a.report_no_index) {
    if (auto err = scenario::report::write_index(a.report); !err.empty()) {
      std::fprintf(stderr, "vplant run: report: %s\n", err.c_str());
      return kExitBadInput;
    }
    if (!a.quiet) std::fprintf(stderr, "  report index: %s/index.html\n", a.report.c_str());
  }
  return rc;
}

}  // namespace

Runner add_run_command(CLI::App& app) {
  auto a = std::make_shared<RunArgs>();
  app.add_option("scenario", a->scenario, "scenario file (YAML, see docs/scenarios.md)")->required();
  app.add_option("--can", a->can, "BUS=IFACE: put a scenario bus on a SocketCAN interface, serve it (BUS=socketcand:ADDR:PORT) or join a remote one (BUS=socketcand-client:HOST:PORT/CHANNEL); repeatable");
  app.add_flag("--realtime", a->realtime, "pace the run by the wall clock (default: virtual time, as fast as possible)");
  app.add_flag("--no-script", a->no_script,
               "leave out the file's script and duration: an external master drives the plant (until --duration or Ctrl-C)");
  app.add_option("--duration", a->duration, "simulated time to run, e.g. 10 or 2.5s (overrides clock.duration)");
  app.add_option("--seed", a->seed, "seed for noise and random faults (overrides clock.seed)")->check(CLI::NonNegativeNumber);
  app.add_option("--trace", a->trace, "write all frames in candump -L format");
  app.add_option("--csv", a->csv, "write the recorded signals as CSV (default signals: every wired port)");
  app.add_option("--junit", a->junit, "write the assertions as JUnit XML");
  app.add_option("--master-report", a->master_report, "write the verdict on the master (its findings) as JSON");
  app.add_flag("--quiet", a->quiet, "print only failures");
  app.add_option("--ui", a->ui,
                 "[ADDR:]PORT: serve the live control plane and dashboard (default address 127.0.0.1; docs/api.md)");
  app.add_flag("--ui-allow-remote", a->ui_allow_remote, "allow --ui on a non-loopback address (no authentication!)");
  app.add_flag("--ui-run", a->ui_run, "virtual time with --ui: start running instead of paused");
  app.add_option("--ui-speed", a->ui_speed, "virtual time with --ui: × wall clock while running (0 = as fast as possible; default 1)")
      ->check(CLI::Range(0.0, 1000.0))
      ->check([](const std::string& v) {
        return std::stod(v) == 0 || std::stod(v) >= 0.001 ? std::string() : std::string("0 or 0.001..1000");
      });
  app.add_flag("--rt", a->rt,
               "real time: run the scheduler's thread SCHED_FIFO (priority 49) with memory locked, where permitted "
               "(docs/runtime.md, \"Real-time priority\")");
  app.add_flag("--power-on-first-client", a->power_on_first_client,
               "a bus served over socketcand: power its nodes when the first client opens it (raw mode), so the "
               "master sees every boot-up (docs/remote.md)");
  app.add_option("--exercises", a->exercises,
                 "with --ui: the folder of exercise files (docs/exercises.md; default: the shipped exercises)");
  app.add_option("--exercise", a->exercise, "with --ui: select this exercise at the start (e.g. nmt, dsp408)");
  app.add_flag("--strict", a->strict, "EDS nodes: reject the CiA 306 deviations that are otherwise loaded with a warning");
  // `vplant test` runs each case of a sweep as its own process (docs/scenarios.md, "matrix").
  app.add_option("--case", a->case_name, "run only this case of the file's matrix")->group("");
  app.add_option("--report", a->report, "write the HTML report into DIR: DIR/index.html and DIR/cases/<case>/ (docs/scenarios.md)");
  app.add_flag("--report-no-index", a->report_no_index, "with --report: write only this run's case, not DIR/index.html (vplant test)")
      ->group("");
  return [a] { return run(*a); };
}

}  // namespace vplant
