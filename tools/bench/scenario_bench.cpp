// Benchmark: the reference plant scenario (all its nodes, full physics) with SYNC every 1 ms, in
// virtual time, without outputs. Prints simulated seconds per CPU second of this process
// (CLOCK_PROCESS_CPUTIME_ID; target >= 500x on one core) and per wall second, ns of CPU per tick,
// and the frames per second of simulated time. A second run with the tick profile on
// (sim/tick_profile.h) gives the split between plant, ODE, nodes and bus delivery, scaled to the
// first run's CPU time per tick.
//   scenario_bench [SCENARIO] [--duration S] [--no-split]
//   (default: scenarios/reference-plant.yaml, 20 s; --no-split: one run, no profiled run, e.g.
//   under callgrind)
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"
#include "sim/tick_profile.h"

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  std::string path = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
  double duration = 20;
  bool split = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--duration") && i + 1 < argc) duration = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--no-split")) split = false;
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
    const double c0 = cpu_seconds();
    const int rc = runner.run();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = cpu_seconds() - c0;
    const auto& sum = runner.summary();
    std::uint64_t frames = 0;
    for (const auto& b : sum.buses) frames += b.frames;
    const double tick_ns = cpu / static_cast<double>(sum.ticks) * 1e9;
    std::printf("scenario_bench: %s, SYNC 1 ms, %.1f s simulated in %.3f s wall: %.0fx real time "
                "(CPU %.3f s: %.0fx; %.0f frames/s simulated, %.0f ns CPU per 1 ms tick; assertions %zu/%zu passed, exit %d)\n",
                s.name.c_str(), sum.simulated_s, wall, sum.simulated_s / wall, cpu, sum.simulated_s / cpu,
                frames / sum.simulated_s, tick_ns, sum.assertions - sum.failures, sum.assertions, rc);

    if (!split) {
      std::fclose(sink);
      return 0;
    }
    // The split: the same run again with the probes on.
    scenario::Runner profiled(quiet, scenario::default_environment(), o);
    const double overhead = sim::TickProfile::probe_overhead_ns();
    sim::TickProfile profile;
    sim::TickProfile::active = &profile;
    const std::int64_t p0 = sim::TickProfile::now_ns();
    profiled.run();
    const double total = profile.run_ns_without_probes(sim::TickProfile::now_ns() - p0, overhead);
    sim::TickProfile::active = nullptr;
    std::fclose(sink);
    auto share = [&](sim::TickPart part) { return profile.part_ns(part, overhead) / total; };
    const double ode = share(sim::TickPart::Ode), plant = share(sim::TickPart::Plant) - ode;
    const double nodes = share(sim::TickPart::Nodes), bus = share(sim::TickPart::Bus);
    const double rest = 1.0 - plant - ode - nodes - bus;
    std::printf("split per tick (CPU ns, from a profiled run): plant %.0f (%.0f %%), ODE %.0f (%.0f %%), nodes %.0f (%.0f %%), "
                "bus delivery %.0f (%.0f %%), master, wires, recorder and faults %.0f (%.0f %%)\n",
                plant * tick_ns, 100 * plant, ode * tick_ns, 100 * ode, nodes * tick_ns, 100 * nodes, bus * tick_ns,
                100 * bus, rest * tick_ns, 100 * rest);
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
