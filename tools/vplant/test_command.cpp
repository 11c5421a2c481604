// `vplant test PATH...`: every scenario case under the paths (suite_selection.h), each a
// `vplant run FILE --case NAME` child process of this same binary (case_pool.h), -j at a time,
// with a per-case timeout; a summary table, one merged JUnit, the HTML report's index. Exit codes
// as `vplant run`: 0 every case passed, 1 a case failed (an assertion, a crash, a timeout),
// 2 bad input (a file that does not load, a bad option, an output that cannot be written).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "engine/reporting/junit_merge.h"
#include "engine/reporting/html/report_writer.h"
#include "engine/reporting/speed_text.h"
#include "engine/loading/yaml_fields.h"
#include "tools/vplant/case_pool.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exit_codes.h"
#include "tools/vplant/suite_selection.h"

namespace vplant {

namespace {

namespace fs = std::filesystem;

constexpr const char* kDefaultTimeout = "10min";
constexpr std::size_t kShownOutput = 64 * 1024;  ///< of a failed case's output, the last bytes
constexpr std::size_t kJunitLimit = std::size_t{64} << 20;  ///< a case's JUnit file read for the merge, at most

struct TestArgs {
  std::vector<std::string> paths;
  std::size_t jobs = 0;
  std::string shard = "1/1";
  std::string filter;
  std::string junit;
  std::string report;
  long long seed = -1;
  std::string timeout = kDefaultTimeout;
  bool list = false;
};

struct Outcome {
  enum class Kind { Pass, Fail, Error, Timeout, Crash, Stopped, NotRun } kind = Kind::NotRun;
  std::string detail;  ///< e.g. "signal 11"
  double simulated_s = -1;
  double wall_s = 0;
};

const char* kind_text(Outcome::Kind k) {
  switch (k) {
    case Outcome::Kind::Pass: return "PASS";
    case Outcome::Kind::Fail: return "FAIL";
    case Outcome::Kind::Error: return "ERROR";
    case Outcome::Kind::Timeout: return "TIMEOUT";
    case Outcome::Kind::Crash: return "CRASH";
    case Outcome::Kind::Stopped: return "STOPPED";
    case Outcome::Kind::NotRun: return "NOT RUN";
  }
  return "?";
}

std::string read_text(const std::string& path, std::size_t last_bytes) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {};
  std::fseek(f, 0, SEEK_END);
  const long size = std::ftell(f);
  const long from = std::max(0L, size - static_cast<long>(last_bytes));
  std::fseek(f, from, SEEK_SET);
  std::string text(static_cast<std::size_t>(size - from), '\0');
  text.resize(std::fread(text.data(), 1, text.size(), f));
  std::fclose(f);
  return from > 0 ? "[... the first " + std::to_string(from) + " bytes left out ...]\n" + text : text;
}

/// The simulated time a case's JUnit file records (-1 when it has none).
double simulated_seconds(const std::string& junit_xml) {
  const std::string key = "name=\"simulated_seconds\" value=\"";
  const auto at = junit_xml.find(key);
  return at == std::string::npos ? -1 : std::atof(junit_xml.c_str() + at + key.size());
}

std::string this_program() {
  std::error_code ec;
  const auto path = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("/proc/self/exe") : path.string();
}

std::string seconds_text(double s) {
  if (s < 0) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", s);
  return buf;
}

int run_tests(const TestArgs& a) {
  const auto shard = parse_shard(a.shard);
  if (!shard) {
    std::fprintf(stderr, "vplant test: --shard '%s' is not K/N with 1 <= K <= N\n", a.shard.c_str());
    return kExitBadInput;
  }
  std::string problem;
  const auto timeout = scenario::parse_duration(a.timeout, &problem);
  if (!timeout) {
    std::fprintf(stderr, "vplant test: --timeout '%s' %s\n", a.timeout.c_str(), problem.c_str());
    return kExitBadInput;
  }
  const auto files = find_scenario_files(a.paths, problem);
  if (!problem.empty()) {
    std::fprintf(stderr, "vplant test: %s\n", problem.c_str());
    return kExitBadInput;
  }
  if (files.empty()) {
    std::fprintf(stderr, "vplant test: no scenario files (*.yaml) under the paths\n");
    return kExitBadInput;
  }
  const auto all = expand_cases(files);
  const auto cases = select_cases(all, a.filter, *shard);
  if (!a.filter.empty() && select_cases(all, a.filter, Shard{}).empty()) {
    std::fprintf(stderr, "vplant test: no case matches --filter '%s'\n", a.filter.c_str());
    return kExitBadInput;
  }
  if (a.list) {
    int rc = kExitOk;
    for (const auto& c : cases) {
      std::printf("%s\n", c.name.c_str());
      if (!c.error.empty()) {
        std::fprintf(stderr, "%s\n", c.error.c_str());
        rc = kExitBadInput;
      }
    }
    return rc;
  }

  std::string tmp_template = (fs::temp_directory_path() / "vplant-test-XXXXXX").string();
  if (!::mkdtemp(tmp_template.data())) {
    std::fprintf(stderr, "vplant test: cannot create a folder in %s\n", fs::temp_directory_path().c_str());
    return kExitBadInput;
  }
  const fs::path tmp = tmp_template;
  // Case i writes its JUnit to tmp/i.xml and its output to tmp/i.out.
  auto junit_of = [&tmp](std::size_t i) { return (tmp / (std::to_string(i) + ".xml")).string(); };
  auto output_of = [&tmp](std::size_t i) { return (tmp / (std::to_string(i) + ".out")).string(); };
  const std::string program = this_program();
  std::vector<PoolJob> jobs;
  std::vector<std::size_t> job_case;  // the case of each job (cases that failed to load run no job)
  std::vector<Outcome> outcomes(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& c = cases[i];
    if (!c.error.empty()) {
      outcomes[i].kind = Outcome::Kind::Error;
      continue;
    }
    PoolJob job;
    job.argv = {program, "run", c.file, "--case", c.name, "--junit", junit_of(i)};
    if (a.seed >= 0) job.argv.insert(job.argv.end(), {"--seed", std::to_string(a.seed)});
    if (!a.report.empty()) job.argv.insert(job.argv.end(), {"--report", a.report, "--report-no-index"});
    job.output = output_of(i);
    jobs.push_back(std::move(job));
    job_case.push_back(i);
  }

  std::size_t name_width = 4;
  for (const auto& c : cases) name_width = std::max(name_width, c.name.size());
  name_width = std::min<std::size_t>(name_width, 72);
  std::size_t finished = 0;
  auto report_case = [&](std::size_t i) {
    const auto& o = outcomes[i];
    std::printf("[%zu/%zu] %-7s %s (%.2f s)%s%s\n", ++finished, cases.size(), kind_text(o.kind), cases[i].name.c_str(),
                o.wall_s, o.detail.empty() ? "" : ": ", o.detail.c_str());
    if (o.kind != Outcome::Kind::Pass) {
      const std::string text = cases[i].error.empty() ? read_text(output_of(i), kShownOutput)
                                                      : cases[i].error + "\n";
      std::string indented;
      std::size_t start = 0;
      while (start < text.size()) {
        const auto nl = text.find('\n', start);
        indented += "    | " + text.substr(start, nl == std::string::npos ? std::string::npos : nl - start + 1);
        if (nl == std::string::npos) indented += "\n";
        start = nl == std::string::npos ? text.size() : nl + 1;
      }
      std::fputs(indented.c_str(), stdout);
    }
    std::fflush(stdout);
  };
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (!cases[i].error.empty()) report_case(i);

  PoolOptions pool;
  pool.jobs = a.jobs ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  pool.timeout = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::microseconds(timeout->count()));
  const auto wall_start = std::chrono::steady_clock::now();
  const int stop_signal = run_pool(jobs, pool, [&](std::size_t job, const PoolResult& r) {
    const std::size_t i = job_case[job];
    auto& o = outcomes[i];
    o.wall_s = r.wall_s;
    o.simulated_s = simulated_seconds(read_text(junit_of(i), kJunitLimit));
    switch (r.end) {
      case PoolResult::End::Exited:
        o.kind = r.code == kExitOk ? Outcome::Kind::Pass
                 : r.code == kExitAssertionFailed ? Outcome::Kind::Fail
                 : r.code == kExitBadInput ? Outcome::Kind::Error
                                           : Outcome::Kind::Crash;
        if (o.kind == Outcome::Kind::Crash) o.detail = "exit code " + std::to_string(r.code);
        break;
      case PoolResult::End::Signalled:
        o.kind = Outcome::Kind::Crash;
        o.detail = "signal " + std::to_string(r.code) + " (" + ::strsignal(r.code) + ")";
        break;
      case PoolResult::End::TimedOut:
        o.kind = Outcome::Kind::Timeout;
        o.detail = "stopped after the --timeout of " + a.timeout;
        break;
      case PoolResult::End::Stopped: o.kind = Outcome::Kind::Stopped; break;
      case PoolResult::End::NotStarted: o.kind = Outcome::Kind::NotRun; return;
    }
    report_case(i);
  });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  // The table, in case order.
  std::printf("\n%-*s  %-7s  %11s  %10s  %s\n", static_cast<int>(name_width), "case", "result", "simulated", "wall", "speed");
  std::size_t count[7] = {};
  double case_wall = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& o = outcomes[i];
    ++count[static_cast<int>(o.kind)];
    case_wall += o.wall_s;
    const std::string speed = o.simulated_s >= 0 ? scenario::real_time_factor_text(o.simulated_s, o.wall_s) : "-";
    std::printf("%-*s  %-7s  %11s  %10s  %s\n", static_cast<int>(name_width), cases[i].name.c_str(), kind_text(o.kind),
                seconds_text(o.simulated_s).c_str(), seconds_text(o.wall_s).c_str(), speed.c_str());
  }
  std::printf("%zu cases: %zu passed, %zu failed, %zu errors, %zu timed out, %zu crashed", cases.size(),
              count[static_cast<int>(Outcome::Kind::Pass)], count[static_cast<int>(Outcome::Kind::Fail)],
              count[static_cast<int>(Outcome::Kind::Error)], count[static_cast<int>(Outcome::Kind::Timeout)],
              count[static_cast<int>(Outcome::Kind::Crash)]);
  if (stop_signal)
    std::printf(", %zu stopped, %zu not run", count[static_cast<int>(Outcome::Kind::Stopped)],
                count[static_cast<int>(Outcome::Kind::NotRun)]);
  if (shard->count > 1) std::printf(" (shard %zu/%zu)", shard->index, shard->count);
  std::printf("; %.2f s wall, %.2f s in the cases, -j %zu\n", wall, case_wall, pool.jobs);

  int rc = count[static_cast<int>(Outcome::Kind::Error)] ? kExitBadInput
           : count[static_cast<int>(Outcome::Kind::Pass)] == cases.size() ? kExitOk
                                                                         : kExitAssertionFailed;
  if (!a.junit.empty()) {
    std::vector<std::string> suites;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto& o = outcomes[i];
      // A case that ran to its end wrote its own suite; one that crashed, hung or did not load
      // gets a suite with the reason and its output.
      const bool ran = o.kind == Outcome::Kind::Pass || o.kind == Outcome::Kind::Fail;
      const auto own = ran ? scenario::junit_testsuites(read_text(junit_of(i), kJunitLimit))
                           : std::vector<std::string>();
      if (!own.empty()) {
        suites.insert(suites.end(), own.begin(), own.end());
        continue;
      }
      const std::string message = std::string(kind_text(o.kind)) + (o.detail.empty() ? "" : ": " + o.detail);
      const std::string output =
          cases[i].error.empty() ? read_text(output_of(i), kShownOutput) : cases[i].error;
      suites.push_back(scenario::junit_error_suite(cases[i].name, message, output, o.wall_s));
    }
    std::error_code ec;
    if (const auto parent = fs::path(a.junit).parent_path(); !parent.empty()) fs::create_directories(parent, ec);
    if (const auto error = scenario::write_merged_junit(a.junit, suites); !error.empty()) {
      std::fprintf(stderr, "vplant test: %s\n", error.c_str());
      rc = kExitBadInput;
    } else {
      std::printf("junit: %s\n", a.junit.c_str());
    }
  }
  if (!a.report.empty()) {
    if (const auto error = scenario::report::write_index(a.report); !error.empty()) {
      std::fprintf(stderr, "vplant test: %s\n", error.c_str());
      rc = kExitBadInput;
    }
  }
  std::error_code ec;
  fs::remove_all(tmp, ec);
  return rc;
}

}  // namespace

Runner add_test_command(CLI::App& app) {
  auto a = std::make_shared<TestArgs>();
  app.add_option("paths", a->paths, "scenario files and folders (searched recursively for *.yaml, not *.plant.yaml)")
      ->required();
  app.add_option("-j,--jobs", a->jobs, "cases at a time (default: the number of cores)")->check(CLI::Range(1, 256));
  app.add_option("--shard", a->shard, "K/N: run the K-th of N disjoint parts of the suite (round-robin over the sorted cases)");
  app.add_option("--filter", a->filter, "run only the cases whose name matches this glob (e.g. 'fault-*')");
  app.add_flag("--list", a->list, "print the names of the cases (of this shard, after --filter) and run nothing");
  app.add_option("--junit", a->junit, "write one JUnit XML for the suite: a testsuite per case, a testcase per assertion");
  app.add_option("--report", a->report, "write the HTML report of every case and its index to this folder");
  app.add_option("--seed", a->seed, "seed for noise and random faults of every case (overrides clock.seed)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--timeout", a->timeout,
                 std::string("wall time per case, e.g. 90s or 5min; a case past it is stopped and reported (default ") +
                     kDefaultTimeout + "; 0 = none)");
  return [a] { return run_tests(*a); };
}

}  // namespace vplant
