// Benchmark: what the live control plane costs the simulation. The reference plant (SYNC 1 ms,
// its script) three ways: UI off, UI on without clients, UI on with one in-process client
// streaming everything (frames, nodes, four signals at 50 Hz). Virtual time: simulated seconds per
// CPU second of the scheduler's thread and of the whole process (the server threads included),
// and per wall second. Real time (no script, the plant idling after boot): tick lateness.
//   ui_bench [--duration S] [--realtime S] [--repeat N] [--only off|on|stream|page] [--issue21-only]
//   (defaults: 10 s virtual, 3 s real time, all three ways; --duration 0 skips virtual time,
//   --realtime 0 real time). With
//   --only, one way and not the issue-21 figures (for perf or callgrind: --toggle-collect='scenario::Runner::run()' counts the
//   scheduler's thread alone).
#include <httplib.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "control/control_plane.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"

namespace {

// Page: what the dashboard opens (issue 21): one stream with a node's dictionary as deltas, four
// signals at 10 Hz, frames, faults and clock; no polls.
enum class Mode { Off, On, Streaming, Page };
const char* name(Mode m) {
  return m == Mode::Off ? "UI off" : m == Mode::On ? "UI on, no client" : m == Mode::Streaming ? "UI on, 1 client streaming" : "UI on, 1 page open";
}

double cpu_seconds(clockid_t id) {
  timespec ts{};
  ::clock_gettime(id, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

/// Forwards to the control plane and counts what its attach (the dictionary catalogue, the
/// server's start) costs the scheduler's thread: start-up, not a per-tick cost, so the figures
/// leave it out.
class TimedAttach final : public scenario::RunExtension {
 public:
  explicit TimedAttach(scenario::RunExtension& inner) : inner_(inner) {}
  void attach(const scenario::RunContext& c) override {
    const double t0 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
    inner_.attach(c);
    attach_cpu = cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - t0;
  }
  bool before_tick(bool end) override { return inner_.before_tick(end); }
  void detach() override { inner_.detach(); }
  double attach_cpu = 0;

 private:
  scenario::RunExtension& inner_;
};

struct Result {
  double simulated = 0, wall = 0, thread_cpu = 0, process_cpu = 0, attach_cpu = 0;
  scenario::RunSummary summary;
  std::uint64_t stream_bytes = 0, frame_events = 0, frames_dropped = 0;
  std::vector<double> ack_ms;  ///< Page in virtual time: POST /api/sync answered, full speed
};

Result run(const scenario::Scenario& s, Mode mode, bool realtime, double duration) {
  Result r;
  scenario::RunOptions o;
  o.quiet = true;
  o.realtime = realtime;
  o.duration = sim::from_seconds(duration);
  std::FILE* sink = std::tmpfile();
  o.out = sink;
  std::unique_ptr<control::ControlPlane> ui;
  std::unique_ptr<TimedAttach> timed;
  if (mode != Mode::Off) {
    control::UiOptions u;
    u.port = 0;
    u.out = nullptr;
    // Streaming: paused until the client's stream is open (capture runs only while one listens).
    u.clock.start_paused = mode == Mode::Streaming || mode == Mode::Page;
    u.clock.speed = 0;
    ui = std::make_unique<control::ControlPlane>(u);
    if (auto err = ui->bind(); !err.empty()) {
      std::fprintf(stderr, "ui_bench: %s\n", err.c_str());
      std::exit(2);
    }
    timed = std::make_unique<TimedAttach>(*ui);
    o.extension = timed.get();
  }
  scenario::Runner runner(s, scenario::default_environment(), o);
  std::atomic<bool> done{false};
  // With a control plane a virtual run pauses at its end instead of ending: stop it there.
  std::thread stopper([&] {
    if (!ui || realtime) return;  // real time ends at its duration
    while (!done) {
      if (ui->bridge().attached() && ui->bridge().clock().end_reached) {
        runner.request_stop();
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  });
  std::atomic<bool> resumed{false};
  std::chrono::steady_clock::time_point resumed_at;
  std::thread client([&] {
    if (mode != Mode::Streaming && mode != Mode::Page) return;
    while (!ui->bridge().attached() && !done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    httplib::Client c("127.0.0.1", ui->port());
    c.set_read_timeout(5, 0);
    const std::string signals = "signals=cyl.position,pump.swivel_angle,p_supply.pressure,shaft.speed";
    c.Get(mode == Mode::Page ? ("/api/events?node=dsv&rate=10&" + signals).c_str() : ("/api/events?rate=50&" + signals).c_str(),
          [&](const char* data, std::size_t n) {
            if (!resumed.exchange(true)) {
              resumed_at = std::chrono::steady_clock::now();
              ui->bridge().resume(0.0);
            }
            r.stream_bytes += n;
            for (const char* p = data; (p = static_cast<const char*>(std::memchr(p, 'e', static_cast<std::size_t>(data + n - p)))); ++p)
              if (static_cast<std::size_t>(data + n - p) >= 13 && !std::strncmp(p, "event: frames", 13)) ++r.frame_events;
            return !done.load();
          });
  });
  // A click at full speed: a command that waits for the simulation (POST /api/sync), 20 times.
  std::thread clicker([&] {
    if (mode != Mode::Page || realtime) return;
    while (!resumed && !done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    httplib::Client c("127.0.0.1", ui->port());
    for (int k = 0; k < 20 && !done; ++k) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const auto t = std::chrono::steady_clock::now();
      const auto res = c.Post("/api/sync", "{\"period_ms\": 0}", "application/json");
      if (res && res->status == 200)
        r.ack_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count());
    }
  });
  const auto w0 = std::chrono::steady_clock::now();
  const double p0 = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID), t0 = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
  runner.run();
  r.attach_cpu = timed ? timed->attach_cpu : 0;
  r.thread_cpu = cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - t0 - r.attach_cpu;
  r.process_cpu = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - p0 - r.attach_cpu;
  const auto w1 = std::chrono::steady_clock::now();
  // The client takes what the hub still has for it (not measured: the run is over).
  if (mode == Mode::Streaming || mode == Mode::Page) std::this_thread::sleep_for(std::chrono::seconds(1));
  done = true;
  stopper.join();
  client.join();
  clicker.join();
  r.wall = std::chrono::duration<double>(w1 - (resumed ? resumed_at : w0)).count();
  r.summary = runner.summary();
  if (ui) r.frames_dropped = ui->bridge().frames_dropped();
  r.simulated = r.summary.simulated_s;
  std::fclose(sink);
  return r;
}

/// The figures issue 21 asks for ("Cheap to watch"), against their targets.
void print_issue21_figures(const scenario::Scenario& s, const scenario::Scenario& idle, double duration, double rt_duration) {
  std::printf("ui_bench: issue 21 figures\n");
  if (rt_duration > 0) {
    const auto r = run(idle, Mode::Page, true, rt_duration);
    std::printf("  real time, quiet bus, one page open: vplant CPU %.1f %% of a core (target <= 5 %%)\n",
                100.0 * r.process_cpu / r.wall);
  }
  if (duration > 0) {
    const auto without = run(s, Mode::On, false, duration);
    const auto with = run(s, Mode::Page, false, duration);
    const double a = without.simulated / without.wall, b = with.simulated / with.wall;
    std::printf("  virtual time, full speed: %.0fx without a page, %.0fx with one open: %.0f %% (target >= 90 %%)\n", a, b,
                100.0 * b / a);
    // CPU time, less moved by the machine's load than wall time: the scheduler's thread, and the
    // process (the hub, the HTTP server and this bench's in-process page included).
    std::printf("    per CPU s: scheduler thread %.0fx / %.0fx, process %.0fx / %.0fx (without / with)\n",
                without.simulated / without.thread_cpu, with.simulated / with.thread_cpu, without.simulated / without.process_cpu,
                with.simulated / with.process_cpu);
    auto acks = with.ack_ms;
    std::sort(acks.begin(), acks.end());
    if (!acks.empty())
      std::printf("  a click at full speed (POST /api/sync, %zu times): median %.1f ms, worst %.1f ms (target <= 200 ms)\n",
                  acks.size(), acks[acks.size() / 2], acks.back());
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  double duration = 10, rt_duration = 3;
  int repeat = 1;
  std::vector<Mode> modes{Mode::Off, Mode::On, Mode::Streaming, Mode::Page};
  bool issue_only = false, only = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--duration") && i + 1 < argc) {
      duration = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--realtime") && i + 1 < argc) {
      rt_duration = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--issue21-only")) {
      issue_only = true;
    } else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) {
      const std::string m = argv[++i];
      only = true;
      if (m == "off") modes = {Mode::Off};
      else if (m == "on") modes = {Mode::On};
      else if (m == "stream") modes = {Mode::Streaming};
      else if (m == "page") modes = {Mode::Page};
      else {
        std::fprintf(stderr, "ui_bench: --only takes off, on, stream or page, not '%s'\n", m.c_str());
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: ui_bench [--duration S] [--realtime S] [--repeat N] [--only off|on|stream|page] [--issue21-only]\n");
      return 2;
    }
  }
  const std::string path = VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml";
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  std::string text = buf.str();
  for (auto p = text.find("sync: 10ms"); p != std::string::npos; p = text.find("sync: 10ms")) text.replace(p, 10, "sync: 1ms");
  scenario::Scenario s;
  try {
    s = scenario::parse_scenario(text, path, path.substr(0, path.rfind('/')));
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  s.outputs = {};
  if (duration > 0)
    std::printf("ui_bench: reference plant, SYNC 1 ms, %.0f s virtual time (CPU per thread / process via clock_gettime)\n", duration);
  // Interleaved repeats on a busy machine: the best run of each way is the one least disturbed.
  double best[4] = {0, 0, 0, 0};
  for (int k = 0; k < repeat && duration > 0 && !issue_only; ++k) {
    for (const Mode m : modes) {
      const auto r = run(s, m, false, duration);
      auto& b = best[static_cast<int>(m)];
      b = std::max(b, r.simulated / r.thread_cpu);
      std::printf("  %-26s %6.0fx per scheduler-thread CPU s (%.0f ns per tick), %6.0fx per process CPU s, %6.0fx per wall s", name(m),
                  r.simulated / r.thread_cpu, 1e9 * r.thread_cpu / static_cast<double>(r.summary.ticks), r.simulated / r.process_cpu,
                  r.simulated / r.wall);
      if (m != Mode::Off) std::printf(" (attach %.1f ms left out)", r.attach_cpu * 1e3);
      if (m == Mode::Streaming)
        std::printf(" (%llu frame batches, %llu bytes streamed, %llu frames dropped)", static_cast<unsigned long long>(r.frame_events),
                    static_cast<unsigned long long>(r.stream_bytes), static_cast<unsigned long long>(r.frames_dropped));
      std::printf("\n");
    }
  }
  if (duration > 0 && repeat > 1 && !issue_only) {
    std::printf("  best of %d per scheduler-thread CPU s:", repeat);
    for (const Mode m : modes) {
      const double b = best[static_cast<int>(m)];
      std::printf("  %s %.0fx", name(m), b);
      if (m != Mode::Off && best[0] > 0) std::printf(" (%+.1f %%)", 100.0 * (b / best[0] - 1));
      std::printf(";");
    }
    std::printf("\n");
  }
  scenario::Scenario idle = s;
  idle.script.clear();
  if (!only) print_issue21_figures(s, idle, duration, rt_duration);  // --only: one way, for a profile
  if (rt_duration <= 0 || issue_only) return 0;
  std::printf("ui_bench: reference plant without script, %.0f s real time\n", rt_duration);
  for (int k = 0; k < repeat; ++k) {
    for (const Mode m : modes) {
      const auto r = run(idle, m, true, rt_duration);
      std::printf("  %-26s ticks %llu, overruns %llu, worst tick lateness %lld us, scheduler thread CPU %.1f %%\n", name(m),
                  static_cast<unsigned long long>(r.summary.ticks), static_cast<unsigned long long>(r.summary.overruns),
                  static_cast<long long>(r.summary.max_lateness_us), 100.0 * r.thread_cpu / r.wall);
    }
  }
  return 0;
}
