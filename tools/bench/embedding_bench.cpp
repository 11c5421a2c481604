// Benchmark: the reference plant in-process through the public API against `vplant run` on the
// same scenario file, in CPU time (the machine is shared: wall time is noise).
//   embedding_bench [VPLANT_CLI] [--reps N]
// Prints, per way in, the CPU seconds of one run and the simulated seconds per CPU second:
//   cli      `vplant run reference-plant.yaml --quiet --trace FILE` as a child process (its CPU
//            from getrusage(RUSAGE_CHILDREN)): start-up, load, 6 s with the scripted master, the
//            file's outputs (trace, CSV)
//   library  vplant::Simulation::load_file + run_for(6 s) with the file's script
//            (Options::run_script) and the trace file; CPU from CLOCK_PROCESS_CPUTIME_ID
//   example  the same with examples/cylinder_master's CylinderMaster instead of the script
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>

#include <vplant/simulation.h>

#include "examples/cylinder_master/cylinder_master.h"

namespace {

const std::string kScenario = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
constexpr double kSimulated = 6.0;

double process_cpu() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double children_cpu() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-6;
}

void print(const char* name, double cpu_per_run) {
  std::printf("  %-8s %8.3f CPU s per run   %7.1f simulated s per CPU s\n", name, cpu_per_run, kSimulated / cpu_per_run);
}

}  // namespace

int main(int argc, char** argv) {
  std::string cli = VPLANT_CLI;
  int reps = 3;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    else cli = argv[i];
  }
  const auto dir = std::filesystem::temp_directory_path() / ("embedding_bench." + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string trace = (dir / "trace.log").string();
  std::printf("embedding_bench: reference plant, %.0f s simulated, %d runs each (CPU time)\n", kSimulated, reps);

  const std::string command = "cd '" + dir.string() + "' && '" + cli + "' run '" + kScenario + "' --quiet --trace '" + trace + "'";
  double before = children_cpu();
  for (int r = 0; r < reps; ++r) {
    if (std::system(command.c_str()) != 0) {
      std::fprintf(stderr, "embedding_bench: `%s` failed\n", command.c_str());
      return 1;
    }
  }
  print("cli", (children_cpu() - before) / reps);

  try {
    before = process_cpu();
    for (int r = 0; r < reps; ++r) {
      vplant::Options o;
      o.run_script = true;
      o.trace_file = trace;
      auto sim = vplant::Simulation::load_file(kScenario, o);
      sim.run_for(std::chrono::seconds(6));
      if (!sim.failures().empty()) {
        std::fprintf(stderr, "embedding_bench: %s\n", sim.failures().front().c_str());
        return 1;
      }
    }
    print("library", (process_cpu() - before) / reps);

    before = process_cpu();
    for (int r = 0; r < reps; ++r) {
      vplant::Options o;
      o.trace_file = trace;
      auto sim = vplant::Simulation::load_file(kScenario, o);
      example::CylinderMaster master(sim);
      sim.run_for(std::chrono::seconds(6));
      if (!master.reached()) {
        std::fprintf(stderr, "embedding_bench: the example master did not reach its target\n");
        return 1;
      }
    }
    print("example", (process_cpu() - before) / reps);
  } catch (const vplant::Error& e) {
    std::fprintf(stderr, "embedding_bench: %s\n", e.what());
    return 1;
  }
  std::filesystem::remove_all(dir);
  return 0;
}
