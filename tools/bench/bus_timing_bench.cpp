// Benchmark of the bit-timed virtual bus (sim::Bus, BusTiming::Bit). Prints, per CPU second
// (CLOCK_PROCESS_CPUTIME_ID, the machine may be loaded):
//   1. the cost per frame of frame_bits() and of a bus delivering frames, ideal and bit-timed;
//   2. the reference plant's virtual-time speed with SYNC every 1 ms, timing ideal and bit;
//   3. 127 generic EDS nodes (tests/data/eds/io_module.eds: TPDO1 on every SYNC, TPDO2 on every
//      second) with SYNC every 10 ms on a 1 Mbit/s bus: the bus saturates; delivered frames per
//      second against the theory (bit rate / mean bits of the delivered frames).
//   bus_timing_bench [--duration S]   (simulated seconds of parts 2 and 3, default 5)
#include <time.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"
#include "sim/bus.h"
#include "sim/can_bit_timing.h"

namespace {

double cpu_now() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

struct Sink : sim::FrameReceiver {
  std::uint64_t n = 0;
  void on_frame(const sim::CanFrame&, sim::Time) override { ++n; }
};

std::vector<sim::CanFrame> frame_mix() {
  return {sim::CanFrame::data_frame(0x181, {1, 2, 3, 4, 5, 6, 7, 8}), sim::CanFrame::data_frame(0x080, {}),
          sim::CanFrame::data_frame(0x705, {5}), sim::CanFrame::data_frame(0x281, {0x10, 0x27, 0, 0}),
          sim::CanFrame::data_frame(0x581, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0, 0})};
}

void per_frame_cost() {
  const auto mix = frame_mix();
  const int n = 2000000;
  unsigned sum = 0;
  double c0 = cpu_now();
  for (int i = 0; i < n; ++i) sum += sim::frame_bits(mix[static_cast<std::size_t>(i) % mix.size()]).total();
  const double bits_ns = (cpu_now() - c0) / n * 1e9;
  std::printf("frame_bits(): %.0f ns CPU per frame (checksum %u)\n", bits_ns, sum % 1000);
  for (auto timing : {sim::BusTiming::Ideal, sim::BusTiming::Bit}) {
    sim::Bus bus("bench");
    bus.set_timing(timing, 1000000);
    bus.set_tx_queue_depth(64);
    Sink a, b, c;
    const int ea = bus.attach(&a);
    bus.attach(&b);
    bus.attach(&c);
    std::size_t next = 0;
    const std::int64_t ticks = 200000;  // 200 s at 1 ms: the bus saturated (bit) or 10 frames a tick (ideal)
    c0 = cpu_now();
    for (std::int64_t t = 0; t < ticks; ++t) {
      const sim::Time now{sim::Duration{t * 1000}};
      const std::size_t top = timing == sim::BusTiming::Bit ? 32 : 10;
      while (bus.pending_frames() < top) bus.send(ea, mix[next++ % mix.size()], now);
      bus.deliver(now);
    }
    const double cpu = cpu_now() - c0;
    const auto frames = bus.stats().frames;
    std::printf("bus %s: %llu frames delivered to 2 receivers, %.0f ns CPU per frame (send + arbitration + delivery)\n",
                timing == sim::BusTiming::Bit ? "bit-timed" : "ideal    ", static_cast<unsigned long long>(frames),
                cpu / static_cast<double>(frames) * 1e9);
  }
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

struct RunFigures {
  double simulated = 0, cpu = 0;
  std::uint64_t frames = 0;
  int rc = 0;
  double busy_bits = 0, bit_rate = 0;
  std::string load_text;
};

RunFigures run(scenario::Scenario s, double duration) {
  s.outputs = {};
  scenario::RunOptions o;
  o.quiet = true;
  o.duration = sim::from_seconds(duration);
  std::FILE* sink = std::tmpfile();
  o.out = sink;
  scenario::Runner runner(s, scenario::default_environment(), o);
  const double c0 = cpu_now();
  RunFigures f;
  f.rc = runner.run();
  f.cpu = cpu_now() - c0;
  std::fclose(sink);
  f.simulated = runner.summary().simulated_s;
  for (const auto& b : runner.summary().buses) {
    f.frames += b.frames;
    f.load_text += b.load;
    f.busy_bits += static_cast<double>(b.busy_bits);
    f.bit_rate = b.bit_rate;
  }
  return f;
}

void reference_plant(double duration) {
  const std::string path = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
  std::string text = read(path);
  for (auto p = text.find("sync: 10ms"); p != std::string::npos; p = text.find("sync: 10ms")) text.replace(p, 10, "sync: 1ms");
  const auto base = scenario::parse_scenario(text, path, path.substr(0, path.rfind('/')));
  for (auto timing : {sim::BusTiming::Ideal, sim::BusTiming::Bit}) {
    auto s = base;
    for (auto& b : s.buses) b.timing = timing;
    const auto f = run(s, duration);
    std::printf("reference plant, SYNC 1 ms, timing %s: %.1f s simulated in %.3f s CPU: %.0fx real time per CPU second, "
                "%.0f frames/s (exit %d)\n",
                timing == sim::BusTiming::Bit ? "bit  " : "ideal", f.simulated, f.cpu, f.simulated / f.cpu,
                static_cast<double>(f.frames) / f.simulated, f.rc);
  }
}

void many_nodes(double duration) {
  std::string text = "name: 127 generic EDS nodes, SYNC 10 ms, 1 Mbit/s\nbuses:\n  - {name: main, bitrate: 1000000}\nnodes:\n";
  for (int id = 1; id <= 127; ++id)
    text += "  - {name: n" + std::to_string(id) + ", device: eds, eds: " VPLANT_SOURCE_DIR "/tests/data/eds/io_module.eds, node_id: " +
            std::to_string(id) + "}\n";
  text += "script:\n  - wait: 100ms\n  - nmt: start\n  - sync: 10ms\n";
  const auto s = scenario::parse_scenario(text, "many-nodes.yaml", ".");
  // TPDO1 of 127 nodes every SYNC, TPDO2 every second SYNC, the SYNC itself.
  const double offered = 100.0 * (127 + 127 / 2.0 + 1);
  const auto f = run(s, duration);
  std::printf("127 EDS nodes, SYNC 10 ms, 1 Mbit/s: %.1f s simulated in %.3f s CPU (%.1fx real time per CPU second)\n",
              f.simulated, f.cpu, f.simulated / f.cpu);
  const double fps = static_cast<double>(f.frames) / f.simulated;
  const double mean_bits = f.busy_bits / static_cast<double>(f.frames);
  const double theory = f.bit_rate / mean_bits;
  std::printf("  offered %.0f frames/s; delivered %.0f frames/s; theory for the delivered mix (%.1f bits/frame) %.0f "
              "frames/s: %.2f %%\n%s",
              offered, fps, mean_bits, theory, fps / theory * 100, f.load_text.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  double duration = 5;
  for (int i = 1; i < argc; ++i)
    if (!std::strcmp(argv[i], "--duration") && i + 1 < argc) duration = std::atof(argv[++i]);
  try {
    per_frame_cost();
    reference_plant(duration);
    many_nodes(duration);
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
