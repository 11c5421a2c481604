// Benchmark: memory of an endless run. The reference plant for one hour of simulated time (the
// script, then the plant idling with every node's PDOs and SYNC) with every output on: candump
// trace, CSV, JUnit and the HTML report (--report: its plots, bounded trace sample and events),
// written to a temporary directory that is removed after.
// Prints the process's resident set size (RSS, /proc/self/statm) every 300 s of simulated time,
// read beside the run from the CSV's last flushed row, and the growth from 60 s to the end
// (target: flat within 1 MB).
//   memory_bench [SCENARIO] [--duration S]     (default: scenarios/reference-plant.yaml, 3600 s)
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"

namespace {

double rss_mib() {
  long pages_total = 0, pages_resident = 0;
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  if (std::fscanf(f, "%ld %ld", &pages_total, &pages_resident) != 2) pages_resident = 0;
  std::fclose(f);
  return static_cast<double>(pages_resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// The time_s of the last complete row the recorder has flushed to the CSV (-1 if none yet).
double csv_simulated_s(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return -1;
  char tail[4096];
  std::fseek(f, 0, SEEK_END);
  const long size = std::ftell(f);
  const long from = size > static_cast<long>(sizeof tail) ? size - static_cast<long>(sizeof tail) : 0;
  std::fseek(f, from, SEEK_SET);
  const std::size_t n = std::fread(tail, 1, sizeof tail - 1, f);
  std::fclose(f);
  tail[n] = '\0';
  // The last '\n' ends the last complete row; the row starts after the '\n' before it.
  char* end = std::strrchr(tail, '\n');
  if (!end) return -1;
  *end = '\0';
  char* start = std::strrchr(tail, '\n');
  start = start ? start + 1 : tail;
  return start[0] >= '0' && start[0] <= '9' ? std::atof(start) : -1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
  double duration = 3600;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--duration") && i + 1 < argc) duration = std::atof(argv[++i]);
    else path = argv[i];
  }
  char dir_template[] = "/tmp/vplant-memory-bench-XXXXXX";
  if (!::mkdtemp(dir_template)) {
    std::perror("memory_bench: mkdtemp");
    return 2;
  }
  const std::string dir = dir_template;
  int rc = 0;
  try {
    scenario::Scenario s = scenario::load_scenario_file(path);
    // Every output on, into the temporary directory (the report draws the file's plots).
    s.outputs.trace = dir + "/trace.log";
    const std::string csv = dir + "/run.csv";
    if (!s.outputs.csv) s.outputs.csv = scenario::CsvSpec{};
    s.outputs.csv->file = csv;
    s.outputs.junit = dir + "/run.xml";
    scenario::RunOptions o;
    o.quiet = true;
    o.report_dir = dir + "/report";
    o.duration = sim::from_seconds(duration);
    std::FILE* sink = std::tmpfile();
    o.out = sink;
    scenario::Runner runner(s, scenario::default_environment(), o);
    const double rss_built = rss_mib();

    struct Sample {
      double simulated_s, rss;
    };
    std::vector<Sample> samples;
    samples.reserve(64);
    std::atomic<bool> done{false};
    std::thread sampler([&] {
      double next = 60;
      while (!done.load()) {
        const double t = csv_simulated_s(csv);
        if (t >= next) {
          samples.push_back({t, rss_mib()});
          next = next < 300 ? 300 : next + 300;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    rc = runner.run();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    done.store(true);
    sampler.join();
    std::fclose(sink);
    const double rss_end = rss_mib();
    const auto& sum = runner.summary();

    std::printf("memory_bench: %s, %.0f s simulated with trace, CSV every %.0f ms and a report with %zu plots; %.1f s wall, %.1f s CPU\n",
                s.name.c_str(), sum.simulated_s, sim::seconds(s.outputs.sample_period) * 1e3, s.outputs.plots.size(),
                wall, cpu);
    std::printf("  RSS after building the run: %8.2f MiB\n", rss_built);
    for (const auto& smp : samples) std::printf("  RSS at %6.0f s simulated: %8.2f MiB\n", smp.simulated_s, smp.rss);
    std::printf("  RSS after writing the outputs: %8.2f MiB\n", rss_end);
    std::error_code ec;
    std::printf("  trace %.1f MiB, CSV %.1f MiB on disk\n",
                static_cast<double>(std::filesystem::file_size(dir + "/trace.log", ec)) / (1024.0 * 1024.0),
                static_cast<double>(std::filesystem::file_size(csv, ec)) / (1024.0 * 1024.0));
    if (samples.size() >= 2) {
      std::printf("  growth from %.0f s to %.0f s simulated: %+.2f MiB (target: within 1 MB)\n", samples.front().simulated_s,
                  samples.back().simulated_s, samples.back().rss - samples.front().rss);
    }
    std::printf("  run exit code %d\n", rc);
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    rc = 2;
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  return rc == 2 ? 2 : 0;
}
