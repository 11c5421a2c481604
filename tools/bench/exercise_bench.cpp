// Benchmark: what checking an exercise costs the tick. The reference plant (script, SYNC every
// 1 ms, physics) runs in virtual time as fast as possible with the control plane attached, first
// without an exercise, then with one whose current step is never met, one run per goal kind (a
// condition read every tick, a frame pattern compared as every frame crosses, a transition log
// scanned every tick). Prints simulated seconds per CPU second and ns of CPU per tick for each;
// the checks should cost nothing measurable (docs/exercises.md).
//   exercise_bench [--duration S] [--repeat N]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "control/control_plane.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// One step whose goal is never met (so it is checked on every tick of the run).
void write_exercise(const std::filesystem::path& dir, const char* name, const char* goal) {
  std::ofstream(dir / (std::string(name) + ".yaml")) << "title: bench\nintroduction: never done\nsteps:\n"
                                                        "  - title: never\n    text: never\n    goal: "
                                                     << goal << "\n";
}

/// The control plane, but the run ends at its duration (virtual time would wait for a dashboard).
class EndingPlane final : public scenario::RunExtension {
 public:
  explicit EndingPlane(control::ControlPlane& plane) : plane_(plane) {}
  void attach(const scenario::RunContext& c) override { plane_.attach(c); }
  bool before_tick(bool end_reached) override { return !end_reached && plane_.before_tick(false); }
  void detach() override { plane_.detach(); }

 private:
  control::ControlPlane& plane_;
};

/// Simulated seconds per CPU second, and CPU ns per tick, of one run.
void run(const scenario::Scenario& s, double duration, const std::string& dir, const char* exercise, int repeat) {
  double best_ratio = 0, best_tick_ns = 0;
  for (int r = 0; r < repeat; ++r) {
    control::UiOptions u;
    u.clock.start_paused = false;
    u.clock.speed = 0;
    u.out = nullptr;
    u.exercises_dir = dir;
    u.exercise = exercise;
    control::ControlPlane plane(u);
    if (auto err = plane.bind(); !err.empty()) {
      std::fprintf(stderr, "exercise_bench: %s\n", err.c_str());
      std::exit(2);
    }
    scenario::RunOptions o;
    o.quiet = true;
    o.duration = sim::from_seconds(duration);
    std::FILE* sink = std::tmpfile();
    o.out = sink;
    EndingPlane ending(plane);
    o.extension = &ending;
    scenario::Runner runner(s, scenario::default_environment(), o);
    const double c0 = cpu_seconds();
    runner.run();
    const double cpu = cpu_seconds() - c0;
    std::fclose(sink);
    const auto& sum = runner.summary();
    const double ratio = sum.simulated_s / cpu;
    if (ratio > best_ratio) {
      best_ratio = ratio;
      best_tick_ns = cpu / static_cast<double>(sum.ticks) * 1e9;
    }
  }
  std::printf("exercise_bench: %-34s %.0fx real time per CPU second, %.0f ns CPU per 1 ms tick (best of %d)\n",
              *exercise ? exercise : "no exercise", best_ratio, best_tick_ns, repeat);
}

}  // namespace

int main(int argc, char** argv) {
  double duration = 10;
  int repeat = 3;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--duration") && i + 1 < argc) duration = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
  }
  const std::string path = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  for (auto p = text.find("sync: 10ms"); p != std::string::npos; p = text.find("sync: 10ms")) text.replace(p, 10, "sync: 1ms");
  const auto dir = std::filesystem::temp_directory_path() / ("exercise_bench." + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_exercise(dir, "condition-goal", "{signal: cyl.position, above: 1000}");
  write_exercise(dir, "frame-goal", "{frame: {id: 0x7FF, data: \"00\"}}");
  write_exercise(dir, "transition-goal", "{transition: {node: dsv, machine: dsp408, to: FAULT_HOLD}}");
  try {
    auto s = scenario::parse_scenario(text, path, path.substr(0, path.rfind('/')));
    s.outputs = {};
    for (const char* e : {"", "condition-goal", "frame-goal", "transition-goal", ""}) run(s, duration, dir.string(), e, repeat);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exercise_bench: %s\n", e.what());
    std::filesystem::remove_all(dir);
    return 2;
  }
  std::filesystem::remove_all(dir);
  return 0;
}
