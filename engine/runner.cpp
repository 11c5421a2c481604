#include "engine/runner.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>

#include "sim/realtime_setup.h"
#include "sim/scheduler.h"
#include "sim/trace_writer.h"
#include "engine/reporting/bus_report.h"
#include "engine/running/fault_injector.h"
#include "engine/reporting/junit_writer.h"
#include "engine/running/master_monitor.h"
#include "engine/reporting/master_report.h"
#include "engine/running/node_group.h"
#include "engine/reporting/recorder.h"
#include "engine/loading/scenario_cases.h"
#include "engine/reporting/html/case_collector.h"
#include "engine/reporting/html/report_writer.h"
#include "engine/loading/scenario_loader.h"
#include "engine/running/scripted_master.h"
#include "engine/reporting/speed_text.h"
#include "engine/running/tick_assembly.h"
#include "engine/running/world.h"

namespace scenario {

namespace {

std::atomic<Runner*> g_active{nullptr};

std::string prepare_output(const std::string& path) {
  const auto parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return {};
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  return ec ? "cannot create '" + parent.string() + "': " + ec.message() : std::string();
}

double wall_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

struct Runner::Impl {
  const Scenario& scenario;
  RunOptions options;
  Verdicts verdicts;
  RunSummary summary;
  std::unique_ptr<World> world;
  std::unique_ptr<FaultInjector> faults;
  std::unique_ptr<ScriptedMaster> master;
  std::unique_ptr<NodeGroup> nodes;
  std::unique_ptr<MasterMonitor> monitor;
  std::unique_ptr<Recorder> recorder;
  std::unique_ptr<sim::TraceWriter> trace;
  std::unique_ptr<sim::Scheduler> scheduler;
  std::optional<sim::Duration> duration;
  std::string csv_path, trace_path, junit_path;
  std::unique_ptr<report::CaseCollector> report;  // --report DIR

  Impl(const Scenario& s, const RunOptions& o) : scenario(s), options(o) {}

  void log(sim::Time t, const std::string& text) const {
    if (!options.quiet) std::fprintf(options.out, "[%10.3f s] %s\n", sim::seconds(t), text.c_str());
    if (report) report->event(t, text);
  }
};

Runner::Runner(const Scenario& scenario, const Environment& env, const RunOptions& options)
    : env_(env), impl_(std::make_unique<Impl>(scenario, options)) {
  build();
}

void Runner::build() {
  auto& m = *impl_;
  const Scenario& scenario = m.scenario;
  const Environment& env = env_;
  const RunOptions& options = m.options;
  BuildOptions build;
  build.can = options.can;
  build.strict_eds = options.strict_eds;
  m.world = std::make_unique<World>(scenario, env, build, options.seed.value_or(scenario.clock.seed));
  const auto logger = [&m](sim::Time t, const std::string& text) { m.log(t, text); };
  m.faults = std::make_unique<FaultInjector>(*m.world, m.verdicts, logger);
  m.master = std::make_unique<ScriptedMaster>(*m.world, *m.faults, m.verdicts, logger);
  m.nodes = std::make_unique<NodeGroup>(*m.world);

  m.duration = options.duration ? options.duration : scenario.clock.duration;
  bool realtime = options.realtime || scenario.clock.mode == ClockSpec::Mode::RealTime ||
                  (scenario.clock.mode == ClockSpec::Mode::Auto && m.world->any_socketcan());
  if (!m.duration && !m.master->has_script() && !realtime && !options.extension)
    throw LoadError(scenario.clock.mark.line > 0 ? scenario.clock.mark : SourceMark{scenario.file, 0, 0},
                    "nothing ends this run: give the clock a duration (or --duration), a script, or run in real time");

  // Outputs: the command line overrides the file.
  m.trace_path = options.trace.empty() ? scenario.outputs.trace : options.trace;
  m.csv_path = !options.csv.empty() ? options.csv : (scenario.outputs.csv ? scenario.outputs.csv->file : "");
  m.junit_path = options.junit.empty() ? scenario.outputs.junit : options.junit;
  m.recorder = std::make_unique<Recorder>(scenario.outputs.sample_period);
  if (!m.csv_path.empty()) {
    const auto signals = scenario.outputs.csv && !scenario.outputs.csv->signals.empty() ? scenario.outputs.csv->signals
                                                                                        : m.world->wired_signals();
    for (const auto& s : signals) m.recorder->add(m.world->resolve(s), false, true);
  }
  if (!options.report_dir.empty()) m.report = std::make_unique<report::CaseCollector>(scenario, *m.world, *m.recorder);

  m.scheduler = std::make_unique<sim::Scheduler>(scenario.clock.tick, realtime ? sim::ClockMode::RealTime : sim::ClockMode::Virtual);
  m.monitor = std::make_unique<MasterMonitor>(*m.world, scenario.master_rules, scenario.clock.tick, m.faults.get());
  assemble_tick(*m.scheduler, TickParts{*m.world, *m.faults, *m.master, *m.nodes, nullptr, m.monitor.get(), m.recorder.get()});

  if (!m.trace_path.empty()) {
    std::string error = prepare_output(m.trace_path);
    if (error.empty()) m.trace = std::make_unique<sim::TraceWriter>(m.trace_path, error);
    if (!error.empty() || !m.trace->is_open()) throw LoadError(SourceMark{m.trace_path, 0, 0}, error);
    if (realtime) m.trace->set_epoch_offset(static_cast<std::int64_t>(std::time(nullptr)));
    for (auto& bus : m.world->buses()) bus->add_tap(m.trace.get());
  }
  if (!m.csv_path.empty()) {
    std::string error = prepare_output(m.csv_path);
    if (error.empty()) error = m.recorder->open_csv(m.csv_path);
    if (!error.empty()) throw LoadError(SourceMark{m.csv_path, 0, 0}, error);
  }
  scheduler_.store(m.scheduler.get());
}

void Runner::rebuild() {
  scheduler_.store(nullptr);
  const Scenario& scenario = impl_->scenario;
  const RunOptions options = impl_->options;
  impl_.reset();
  impl_ = std::make_unique<Impl>(scenario, options);
  try {
    build();
  } catch (...) {  // e.g. a socketcand port taken meanwhile: the extension's run has ended
    if (options.extension) options.extension->detach();
    throw;
  }
  if (stopping_.load()) impl_->scheduler->request_stop();
}

Runner::~Runner() {
  Runner* self = this;
  g_active.compare_exchange_strong(self, nullptr);
}

void Runner::request_stop() {
  stopping_.store(true);
  if (auto* s = scheduler_.load()) s->request_stop();
}
const Verdicts& Runner::verdicts() const { return impl_->verdicts; }
const RunSummary& Runner::summary() const { return impl_->summary; }
const MasterMonitor& Runner::master_monitor() const { return *impl_->monitor; }
Runner* active_runner() { return g_active.load(); }

int Runner::run() {
  for (;;) {
    bool restarted = false;
    const int rc = run_once(restarted);
    if (!restarted) return rc;
    rebuild();
  }
}

int Runner::run_once(bool& restarted) {
  auto& m = *impl_;
  g_active.store(this);
  auto& sched = *m.scheduler;
  const bool realtime = sched.mode() == sim::ClockMode::RealTime;
  if (m.options.extension) m.options.extension->attach(RunContext{m.scenario, *m.world, *m.faults, sched, m.monitor.get()});
  // Nodes power on now, or (--power-on-first-client) when a client listens on their bus.
  std::vector<std::size_t> waiting_buses;
  for (std::size_t b = 0; b < m.world->buses().size(); ++b) {
    const auto* t = m.world->buses()[b]->transport();
    if (m.options.power_on_first_client && t && !t->peer_listening()) waiting_buses.push_back(b);
  }
  const auto power_bus_nodes = [&m, &sched](std::size_t bus) {
    for (auto& n : m.world->nodes())
      if (n.bus == static_cast<int>(bus)) n.device->power_on(sched.now());
  };
  for (std::size_t b = 0; b < m.world->buses().size(); ++b)
    if (std::find(waiting_buses.begin(), waiting_buses.end(), b) == waiting_buses.end()) power_bus_nodes(b);
  // One line when the nodes are up, so a master programmer (real time, or an external master with
  // --no-script) knows where to connect before anything else happens.
  if (!m.options.quiet && (realtime || m.options.no_script)) {
    std::string line = "vplant run: " + m.scenario.name + " is up:";
    for (std::size_t b = 0; b < m.world->buses().size(); ++b) {
      const auto& bus = *m.world->buses()[b];
      line += (b ? "; bus " : " bus ") + bus.name() + " on " + (bus.transport() ? bus.transport()->where() : std::string("the virtual bus")) + ":";
      for (const auto& n : m.world->nodes())
        if (n.bus == static_cast<int>(b)) line += " " + n.spec->name + "=" + std::to_string(n.node_id);
    }
    if (!waiting_buses.empty()) line += "; nodes power on when a client opens their bus";
    std::fprintf(m.options.out, "%s%s\n", line.c_str(), realtime && !m.duration ? " (Ctrl-C stops)" : "");
    std::fflush(m.options.out);
  }

  // --rt: on this thread (the scheduler's), after the extension started its own threads.
  if (m.options.rt) {
    std::string note = realtime ? sim::enter_realtime().message : "real time: --rt ignored: the run is in virtual time";
    for (auto at = note.find('\n'); at != std::string::npos; at = note.find('\n', at + 1)) note.insert(at + 1, "vplant run: ");
    if (!m.options.quiet) std::fprintf(m.options.out, "vplant run: %s\n", note.c_str());
  }

  const double wall_start = wall_now();
  double next_progress = wall_start + 0.5;
  bool progress_shown = false;
  const std::uint64_t limit_ticks =
      m.duration ? static_cast<std::uint64_t>((m.duration->count() + sched.tick().count() - 1) / sched.tick().count()) : 0;
  while (!sched.stop_requested()) {
    const bool end = m.duration ? sched.stats().ticks >= limit_ticks : (m.master->has_script() && m.master->finished());
    if (m.options.extension ? !m.options.extension->before_tick(end) : end) break;
    if (!waiting_buses.empty()) {
      std::erase_if(waiting_buses, [&](std::size_t b) {
        if (!m.world->buses()[b]->transport()->peer_listening()) return false;
        power_bus_nodes(b);
        m.log(sched.now(), "a client listens on bus " + m.world->buses()[b]->name() + ": its nodes power on");
        return true;
      });
    }
    sched.run_ticks(1);
    if (m.options.progress && (sched.stats().ticks & 255) == 0) {
      const double w = wall_now();
      if (w >= next_progress) {
        next_progress = w + 0.25;
        progress_shown = true;
        const double sim_s = sim::seconds(sched.now());
        if (m.duration) {
          std::fprintf(m.options.out, "\r  %.1f / %.1f s simulated (%s)   ", sim_s, sim::seconds(*m.duration),
                       real_time_factor_text(sim_s, w - wall_start).c_str());
        } else {
          std::fprintf(m.options.out, "\r  %.1f s simulated (%s)   ", sim_s, real_time_factor_text(sim_s, w - wall_start).c_str());
        }
        std::fflush(m.options.out);
      }
    }
  }
  if (progress_shown) std::fprintf(m.options.out, "\r%60s\r", "");
  if (m.options.extension && !sched.stop_requested() && m.options.extension->wants_restart()) {
    // The outputs of this run are dropped: the new run writes them afresh from t = 0.
    if (!m.options.quiet) std::fprintf(m.options.out, "vplant run: restart at %.3f s: the scenario starts again at t = 0\n", sim::seconds(sched.now()));
    restarted = true;
    return 0;
  }
  const double wall = wall_now() - wall_start;
  m.summary.interrupted = sched.stop_requested();
  if (m.options.extension) m.options.extension->detach();
  m.master->finish(sched.now());
  g_active.store(nullptr);

  int rc = m.verdicts.failures() ? 1 : 0;
  // A trace or CSV that lost lines (disk full, EIO) is an output that could not be written.
  for (const std::string& error : {m.recorder->close(), m.trace ? m.trace->close() : std::string()}) {
    if (error.empty()) continue;
    std::fprintf(m.options.out, "vplant run: %s\n", error.c_str());
    rc = 2;
  }
  auto& s = m.summary;
  s.simulated_s = sim::seconds(sched.now());
  s.wall_s = wall;
  s.ticks = sched.stats().ticks;
  s.realtime = realtime;
  s.overruns = sched.stats().overruns;
  s.max_lateness_us = sched.stats().max_lateness.count();
  s.reanchors = sched.stats().reanchors;
  s.slipped_us = sched.stats().slipped.count();
  for (std::size_t i = 0; i < m.world->buses().size(); ++i) {
    const auto& bus = *m.world->buses()[i];
    s.buses.push_back({bus.name(), bus.transport() ? std::string(bus.transport()->name()) : "virtual", bus.stats().frames,
                       describe_bus_load(bus, sim::seconds(sched.now())), bus.stats().busy_bits, bus.timing_bit_rate()});
  }
  s.assertions = m.verdicts.outcomes().size();
  s.failures = m.verdicts.failures();
  s.faults = m.faults->applied();
  const FindingLog& findings = m.monitor->findings();
  for (std::size_t r = 0; r < kMasterRuleCount; ++r) {
    const auto rule = static_cast<MasterRule>(r);
    s.master_findings += findings.count_of(rule);
    if (m.scenario.master_rules.of(rule) == Severity::Error) s.master_errors += findings.count_of(rule);
  }
  if (!m.options.master_report.empty()) {
    std::string error = prepare_output(m.options.master_report);
    if (error.empty()) error = write_master_report(m.options.master_report, *m.monitor);
    if (!error.empty()) {
      std::fprintf(m.options.out, "vplant run: %s\n", error.c_str());
      rc = 2;
    }
  }

  if (!m.junit_path.empty()) {
    std::string error = prepare_output(m.junit_path);
    Verdicts with_rules = m.verdicts;  // the JUnit file adds one test case per master rule
    const SourceMark& rules_mark = m.scenario.master_rules.mark;
    add_rule_outcomes(*m.monitor, rules_mark.line ? rules_mark : SourceMark{m.scenario.file, 0, 0}, sched.now(), with_rules);
    if (error.empty()) error = write_junit(m.junit_path, m.scenario.name, with_rules, wall, s.simulated_s);
    if (!error.empty()) {
      std::fprintf(m.options.out, "vplant run: %s\n", error.c_str());
      rc = 2;
    }
  }
  if (m.report) {
    const auto record = m.report->finish(m.verdicts, s, m.options.seed.value_or(m.scenario.clock.seed), rc);
    if (auto error = report::write_case(m.options.report_dir, record); !error.empty()) {
      std::fprintf(m.options.out, "vplant run: report: %s\n", error.c_str());
      rc = 2;
    }
  }

  FILE* out = m.options.out;
  for (const auto& o : m.verdicts.outcomes()) {
    if (o.passed) continue;
    std::fprintf(out, "%s: FAILED at %.3f s: %s: expected %s, actual %s\n", o.mark.to_string().c_str(),
                 sim::seconds(o.time), o.name.c_str(), o.expected.c_str(), o.actual.c_str());
  }
  if (!m.options.quiet) {
    std::fprintf(out, "vplant run: %s: %.3f s simulated in %.3f s wall (%s)%s\n", m.scenario.name.c_str(), s.simulated_s,
                 s.wall_s, real_time_factor_text(s.simulated_s, s.wall_s).c_str(), s.interrupted ? ", interrupted" : "");
    for (const auto& b : s.buses) {
      std::fprintf(out, "  bus %s (%s): %llu frames\n", b.name.c_str(), b.wire.c_str(), static_cast<unsigned long long>(b.frames));
      std::fputs(b.load.c_str(), out);
    }
    std::fprintf(out, "  nodes: %zu, faults injected: %zu, ticks: %llu", m.world->nodes().size(), s.faults,
                 static_cast<unsigned long long>(s.ticks));
    if (realtime)
      std::fprintf(out, ", overruns: %llu, worst tick lateness: %lld us", static_cast<unsigned long long>(s.overruns),
                   static_cast<long long>(s.max_lateness_us));
    if (s.reanchors)
      std::fprintf(out, " (schedule re-anchored %llu times: simulated time %.1f ms behind the wall clock)",
                   static_cast<unsigned long long>(s.reanchors), static_cast<double>(s.slipped_us) / 1000.0);
    std::fprintf(out, "\n  assertions: %zu passed, %zu failed\n", s.assertions - s.failures, s.failures);
    print_findings(out, *m.monitor, !m.options.master_report.empty());
    if (m.trace) std::fprintf(out, "  trace: %s\n", m.trace_path.c_str());
    if (!m.csv_path.empty()) std::fprintf(out, "  csv: %s (%zu rows)\n", m.csv_path.c_str(), m.recorder->rows());
    if (m.report)
      std::fprintf(out, "  report: %s\n",
                   (std::filesystem::path(m.options.report_dir) / "cases" / report::case_id(m.scenario.name) / "index.html").c_str());
    if (!m.junit_path.empty()) std::fprintf(out, "  junit: %s\n", m.junit_path.c_str());
    if (!m.options.master_report.empty()) std::fprintf(out, "  master report: %s\n", m.options.master_report.c_str());
  }
  return rc;
}

namespace {

/// One case of a file (the whole file when it has no matrix).
int run_case(const ScenarioCases& cases, std::size_t i, bool several, const Environment& env, const RunOptions& options,
             bool& interrupted) {
  try {
    Scenario s = cases.load(i);
    if (options.no_script) {
      // The file's script and duration belong to its scripted master; without it, the run lasts
      // until --duration or, in real time, until SIGINT/SIGTERM.
      s.script.clear();
      s.clock.duration.reset();
      // The file's outputs describe its scripted run; a session for an external master writes
      // only what the command line asks for (--trace, --csv, --junit).
      s.outputs.trace.clear();
      s.outputs.csv.reset();
      s.outputs.junit.clear();
    }
    RunOptions o = options;
    // Several cases of a sweep write the files the command line names side by side.
    if (several)
      for (std::string* path : {&o.trace, &o.csv, &o.junit}) *path = cases.output_path(*path, i);
    if (o.extension_for && !o.extension) o.extension = o.extension_for(s);
    Runner runner(s, env, o);
    const int rc = runner.run();
    interrupted = runner.summary().interrupted;
    return rc;
  } catch (const LoadError& e) {
    std::fprintf(options.out, "%s\n", e.what());
    return 2;
  }
}

}  // namespace

int run_scenario_file(const std::string& path, const Environment& env, const RunOptions& options) {
  try {
    const ScenarioCases cases = ScenarioCases::load_file(path);
    std::vector<std::size_t> selected;
    if (!options.case_name.empty()) {
      const auto i = cases.find(options.case_name);
      if (!i) throw LoadError(SourceMark{path, 0, 0}, "no case named '" + options.case_name + "'");
      selected.push_back(*i);
    } else {
      for (std::size_t i = 0; i < cases.size(); ++i) selected.push_back(i);
    }
    // Every case of a sweep runs; the worst exit code is the run's (2 over 1 over 0).
    int worst = 0;
    bool interrupted = false;
    for (std::size_t k = 0; k < selected.size() && !interrupted; ++k)
      worst = std::max(worst, run_case(cases, selected[k], selected.size() > 1, env, options, interrupted));
    return worst;
  } catch (const LoadError& e) {
    std::fprintf(options.out, "%s\n", e.what());
    return 2;
  }
}

}  // namespace scenario
