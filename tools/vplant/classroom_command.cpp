// `vplant classroom SCENARIO --seats N --ui [ADDR:]PORT`: one plant per trainee in one process
// (docs/classroom.md). Each seat is a whole run of the scenario without its script (the trainee is
// the master): its own buses, nodes, plant, clock and scheduler thread, with the single-plant
// control plane and page under /seats/K/; the trainer's overview is at /. Every link printed at
// the start carries its token; nothing else is ever printed of them. Exit codes: 0 stopped by
// SIGINT/SIGTERM, 2 bad input.
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "control/classroom_server.h"
#include "engine/runner.h"
#include "engine/loading/scenario_cases.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exercise_folder.h"
#include "tools/vplant/exit_codes.h"
#include "tools/vplant/stop_signals.h"

namespace vplant {

namespace {

constexpr std::size_t kMaxSeats = 32;

struct ClassroomArgs {
  std::string scenario;
  std::size_t seats = 0;
  std::string ui;
  bool ui_allow_remote = false;
  bool realtime = false;
  double ui_speed = 1.0;
  std::string exercises;  ///< "" = the shipped folder
};

// The runs a signal stops (a handler may only touch atomics).
std::array<std::atomic<scenario::Runner*>, kMaxSeats> g_runs{};

bool stop_every_seat() {
  bool any = false;
  for (auto& r : g_runs)
    if (auto* runner = r.load()) {
      runner->request_stop();
      any = true;
    }
  return any;
}

/// The scenario a seat runs: the file's, without its script, duration and output files (the
/// trainee drives the plant, for as long as the course lasts). Throws LoadError.
scenario::Scenario seat_scenario(const scenario::ScenarioCases& cases) {
  scenario::Scenario s = cases.load(0);
  s.script.clear();
  s.clock.duration.reset();
  s.outputs.trace.clear();
  s.outputs.csv.reset();
  s.outputs.junit.clear();
  // Seats share nothing: a SocketCAN interface or a socketcand server would be one wire for all.
  for (const auto& bus : s.buses)
    if (!bus.iface.empty())
      throw scenario::LoadError(bus.mark, "classroom: bus '" + bus.name + "' is on '" + bus.iface +
                                              "': seats run on in-process virtual buses only (one wire would be "
                                              "shared by every seat)");
  return s;
}

int run(const ClassroomArgs& a) {
  control::UiOptions ui;
  if (auto err = control::parse_ui_address(a.ui, ui); !err.empty()) {
    std::fprintf(stderr, "vplant classroom: --ui %s\n", err.c_str());
    return kExitBadInput;
  }
  ui.clock.start_paused = false;  // a trainee's plant is live from the start
  ui.clock.speed = a.ui_speed;
  ui.out = nullptr;  // the classroom prints the links
  ui.exercises_dir = a.exercises.empty() ? default_exercises_dir() : a.exercises;
  install_stop_signals(stop_every_seat);

  std::vector<scenario::Scenario> scenarios;
  std::vector<std::unique_ptr<control::ClassroomSeat>> seats;
  std::vector<std::unique_ptr<scenario::Runner>> runners;
  const auto env = scenario::default_environment();
  try {
    const auto cases = scenario::ScenarioCases::load_file(a.scenario);
    if (cases.size() > 1)
      throw scenario::LoadError(scenario::SourceMark{a.scenario, 0, 0},
                                "classroom: the file is a matrix of " + std::to_string(cases.size()) +
                                    " cases; a classroom runs one scenario");
    scenarios.reserve(a.seats);  // the runners keep references to them
    for (std::size_t k = 0; k < a.seats; ++k) {
      scenarios.push_back(seat_scenario(cases));
      seats.push_back(std::make_unique<control::ClassroomSeat>(ui));
      scenario::RunOptions o;
      o.realtime = a.realtime;
      o.quiet = true;
      o.extension = seats.back().get();
      runners.push_back(std::make_unique<scenario::Runner>(scenarios.back(), env, o));
    }
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }

  std::vector<control::ClassroomSeat*> hosted;
  for (auto& s : seats) hosted.push_back(s.get());
  control::ClassroomServer server(control::ClassroomAccess::random(a.seats), hosted);
  if (auto err = server.listen(ui.address, ui.port, a.ui_allow_remote); !err.empty()) {
    std::fprintf(stderr, "vplant classroom: %s\n", err.c_str());
    return kExitBadInput;
  }

  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < a.seats; ++k) {
    g_runs[k].store(runners[k].get());
    threads.emplace_back([&runners, k] { runners[k]->run(); });
  }
  // Serve once every seat is attached: its routes are in place before the first request.
  for (auto& s : seats)
    while (!s->plane().routed() && !s->plane().bridge().finished())
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  server.start();

  const auto links = server.links();
  std::fprintf(stderr, "vplant classroom: %zu seats of '%s' (%s), one link each (hand out, do not post):\n", a.seats,
               scenarios.front().name.c_str(),
               a.realtime ? "real time" : ("virtual time x" + std::to_string(a.ui_speed)).c_str());
  std::fprintf(stderr, "  trainer: %s\n", links[0].c_str());
  for (std::size_t k = 1; k < links.size(); ++k) std::fprintf(stderr, "  seat %zu: %s\n", k, links[k].c_str());
  if (!control::is_loopback(ui.address))
    std::fprintf(stderr, "vplant classroom: listening on %s: a link's token is its only protection (plain HTTP)\n",
                 ui.address.c_str());
  std::fflush(stderr);

  for (auto& t : threads) t.join();
  for (auto& r : g_runs) r.store(nullptr);
  server.stop();
  return kExitOk;
}

}  // namespace

Runner add_classroom_command(CLI::App& app) {
  auto a = std::make_shared<ClassroomArgs>();
  app.add_option("scenario", a->scenario, "scenario file (YAML, docs/scenarios.md): every seat runs it without its script")
      ->required();
  app.add_option("--seats", a->seats, "number of trainees: one plant each (1..32)")
      ->required()
      ->check(CLI::Range(std::size_t{1}, kMaxSeats));
  app.add_option("--ui", a->ui, "[ADDR:]PORT: serve the seats and the trainer's overview (default address 127.0.0.1)")
      ->required();
  app.add_flag("--ui-allow-remote", a->ui_allow_remote,
               "allow --ui on a non-loopback address (the links' tokens guard it: docs/classroom.md)");
  app.add_flag("--realtime", a->realtime, "pace every seat by the wall clock (default: virtual time, see --ui-speed)");
  app.add_option("--ui-speed", a->ui_speed, "virtual time: × wall clock (0 = as fast as possible; default 1)")
      ->check(CLI::Range(0.0, 1000.0))
      ->check([](const std::string& v) {
        return std::stod(v) == 0 || std::stod(v) >= 0.001 ? std::string() : std::string("0 or 0.001..1000");
      });
  app.add_option("--exercises", a->exercises,
                 "the folder of exercise files every seat offers (docs/exercises.md; default: the shipped exercises)")
      ->check(CLI::ExistingDirectory);
  return [a] { return run(*a); };
}

}  // namespace vplant
