// Benchmark: the reference plant scenario (all its nodes, full physics) with SYNC every 1 ms, in
// virtual time, without outputs. Prints simulated seconds per wall second (target >= 500x on one
// core) and the frames per second of simulated time.
//   scenario_bench [SCENARIO] [--duration S]     (default: scenarios/reference-plant.yaml, 20 s)
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/runner.h"
#include "engine/scenario_loader.h"

int main(int argc, char** argv) {
  std::string path = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
  double duration = 20;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--duration") && i + 1 < argc) duration = std::atof(argv[++i]);
    else path = argv[i];
  }
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "scenario_bench: cannot open %s\n", path.c_str());
    return 2;
  }
  std::stringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  // SYNC every 1 ms instead of the file's period; no files written.
  for (auto p = text.find("sync: 10ms"); p != std::string::npos; p = text.find("sync: 10ms")) text.replace(p, 10, "sync: 1ms");
  try {
    const auto s = scenario::parse_scenario(text, path, path.substr(0, path.rfind('/')));
    scenario::Scenario quiet = s;
    quiet.outputs = {};
    scenario::RunOptions o;
    o.quiet = true;
    o.duration = sim::from_seconds(duration);
    std::FILE* sink = std::tmpfile();
    o.out = sink;
    scenario::Runner runner(quiet, scenario::default_environment(), o);
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const int rc = runner.run();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::fclose(sink);
    const auto& sum = runner.summary();
    std::uint64_t frames = 0;
    for (const auto& b : sum.buses) frames += b.frames;
    std::printf("scenario_bench: %s, SYNC 1 ms, %.1f s simulated in %.3f s wall: %.0fx real time "
                "(CPU %.3f s: %.0fx; %.0f frames/s simulated, %.1f us CPU per 1 ms tick; assertions %zu/%zu passed, exit %d)\n",
                s.name.c_str(), sum.simulated_s, wall, sum.simulated_s / wall, cpu, sum.simulated_s / cpu,
                frames / sum.simulated_s, cpu / static_cast<double>(sum.ticks) * 1e6, sum.assertions - sum.failures, sum.assertions, rc);
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
