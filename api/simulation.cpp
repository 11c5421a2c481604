// vplant::Simulation: the scenario engine's pieces (world, fault injector, scripted master,
// nodes, plant) on one virtual-time scheduler, with the caller's endpoints and step functions
// added. The tick is assembled as for engine/runner.cpp (engine/running/tick_assembly.h), minus outputs,
// real time and the CLI's summary.
#include <vplant/simulation.h>

#include <array>
#include <map>

#include "api/error_convert.h"
#include "api/frame_convert.h"
#include "devices/device.h"
#include "engine/running/environment.h"
#include "engine/loading/fault_codec.h"
#include "engine/running/fault_injector.h"
#include "engine/running/node_group.h"
#include "engine/running/outcome.h"
#include "engine/loading/scenario_loader.h"
#include "engine/running/scripted_master.h"
#include "engine/running/tick_assembly.h"
#include "engine/running/world.h"
#include "sim/scheduler.h"
#include "sim/trace_writer.h"

namespace vplant {

namespace {

using detail::fail;

[[noreturn]] void rethrow(const scenario::LoadError& e) { throw detail::to_error(e.diagnostic()); }

/// The plant's parameter names in one line, for an error about an unknown one.
std::string list_parameters(const scenario::PlantModel& plant) {
  std::string list;
  for (const auto& n : plant.parameter_names()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

/// Marks the simulation as running for one run_for/run_until; a second run from inside it (a step
/// function or frame handler calling run_for) would advance time in the middle of a tick.
class RunGuard {
 public:
  RunGuard(bool& running, const char* call) : running_(running) {
    if (running_)
      fail(std::string(call) + ": called from a step function or frame handler while the simulation runs; "
                               "run the simulation from the caller's code only");
    running_ = true;
  }
  ~RunGuard() { running_ = false; }
  RunGuard(const RunGuard&) = delete;
  RunGuard& operator=(const RunGuard&) = delete;

 private:
  bool& running_;
};

/// Runs the caller's step functions in the order they were added (one scheduler component).
class CallerSteps final : public sim::Steppable {
 public:
  void add(Simulation::StepFunction f) { steps_.push_back(std::move(f)); }
  void step(sim::Time now, sim::Duration dt) override {
    for (auto& s : steps_) s(now.time_since_epoch(), dt);
  }

 private:
  std::vector<Simulation::StepFunction> steps_;
};

class CallerEndpoint final : public Endpoint, public sim::FrameReceiver {
 public:
  CallerEndpoint(sim::Bus& bus, const sim::Scheduler& clock, Simulation::FrameHandler handler)
      : bus_(bus), clock_(clock), handler_(std::move(handler)), id_(bus.attach(this)) {}
  void send(const Frame& frame) override {
    detail::check(frame, "Endpoint::send");
    bus_.send(id_, detail::to_sim(frame), clock_.now());
  }
  const std::string& bus() const override { return bus_.name(); }
  void on_frame(const sim::CanFrame& frame, sim::Time now) override {
    if (handler_) handler_(detail::from_sim(frame), now.time_since_epoch());
  }

 private:
  sim::Bus& bus_;
  const sim::Scheduler& clock_;
  Simulation::FrameHandler handler_;
  int id_;
};

/// Keeps every frame that crosses a bus (Options::record_trace).
class TraceRecorder final : public sim::FrameTap {
 public:
  void on_bus_frame(std::string_view wire_name, const sim::CanFrame& frame, sim::Time now) override {
    frames.push_back(TimedFrame{now.time_since_epoch(), std::string(wire_name), detail::from_sim(frame)});
  }
  std::vector<TimedFrame> frames;
};

/// The last frame of each identifier on one bus, so that a frame(...) signal first asked for
/// after its frame went by still reads it. Standard identifiers in a fixed table (no allocation
/// per frame); extended ones in a map (an allocation on an identifier's first frame only).
class LastFrames final : public sim::FrameTap {
 public:
  void on_bus_frame(std::string_view, const sim::CanFrame& frame, sim::Time) override {
    if (frame.rtr) return;
    if (frame.extended) {
      extended_[frame.id] = frame;
    } else {
      auto& slot = standard_[frame.id & sim::CanFrame::kMaxStdId];
      if (!slot.seen) seen_ids_.push_back(frame.id);  // at most 2048: reserved
      slot = {true, frame};
    }
  }
  /// Feeds every last frame to `store` (after a new signal created its slots).
  void replay(scenario::FrameFieldStore& store, int bus) const {
    for (auto id : seen_ids_) store.on_frame(bus, standard_[id].frame);
    for (const auto& [id, f] : extended_) store.on_frame(bus, f);
  }
  LastFrames() { seen_ids_.reserve(sim::CanFrame::kMaxStdId + 1); }

 private:
  struct Slot {
    bool seen = false;
    sim::CanFrame frame;
  };
  std::array<Slot, sim::CanFrame::kMaxStdId + 1> standard_{};
  std::vector<std::uint32_t> seen_ids_;
  std::map<std::uint32_t, sim::CanFrame> extended_;
};

}  // namespace

struct Simulation::Impl {
  Options options;
  std::unique_ptr<scenario::Scenario> scenario;
  scenario::Verdicts verdicts;
  std::unique_ptr<scenario::World> world;
  std::unique_ptr<scenario::FaultInjector> faults;
  std::unique_ptr<scenario::ScriptedMaster> master;
  std::unique_ptr<scenario::NodeGroup> nodes;
  CallerSteps caller_steps;
  std::unique_ptr<sim::Scheduler> scheduler;
  TraceRecorder recorder;
  std::unique_ptr<sim::TraceWriter> trace_file;
  std::vector<std::unique_ptr<CallerEndpoint>> endpoints;
  std::vector<std::unique_ptr<LastFrames>> last_frames;  // per bus
  std::map<std::string, scenario::Signal, std::less<>> signals;
  bool running = false;  // inside run_for/run_until (RunGuard)

  void build();
  void flush() {
    if (trace_file) trace_file->flush();
  }
};

void Simulation::Impl::build() {
  auto& s = *scenario;
  if (s.clock.mode == scenario::ClockSpec::Mode::RealTime)
    throw scenario::LoadError(s.clock.mark, "the library runs in virtual time only (clock mode realtime)");
  for (const auto& b : s.buses)
    if (!b.iface.empty())
      throw scenario::LoadError(b.mark, "bus '" + b.name + "' is on SocketCAN '" + b.iface +
                                            "': the library runs its buses in-process (transport: virtual)");
  if (!options.run_script) {
    s.script.clear();
    s.clock.duration.reset();
  }
  world = std::make_unique<scenario::World>(s, scenario::default_environment(), scenario::BuildOptions{},
                                            options.seed.value_or(s.clock.seed));
  const auto quiet = [](sim::Time, const std::string&) {};
  faults = std::make_unique<scenario::FaultInjector>(*world, verdicts, quiet);
  // Also with an empty script: it feeds the frame fields that frame(...) signals read.
  master = std::make_unique<scenario::ScriptedMaster>(*world, *faults, verdicts, quiet);
  nodes = std::make_unique<scenario::NodeGroup>(*world);

  scheduler = std::make_unique<sim::Scheduler>(s.clock.tick, sim::ClockMode::Virtual);
  scenario::assemble_tick(*scheduler, scenario::TickParts{*world, *faults, *master, *nodes, &caller_steps, nullptr, nullptr});

  for (auto& bus : world->buses()) {
    last_frames.push_back(std::make_unique<LastFrames>());
    bus->add_tap(last_frames.back().get());
    if (options.record_trace) bus->add_tap(&recorder);
  }
  if (!options.trace_file.empty()) {
    std::string error;
    trace_file = std::make_unique<sim::TraceWriter>(options.trace_file, error);
    if (!error.empty() || !trace_file->is_open()) throw scenario::LoadError(scenario::SourceMark{options.trace_file, 0, 0}, error);
    for (auto& bus : world->buses()) bus->add_tap(trace_file.get());
  }
  for (auto& n : world->nodes()) n.device->power_on(scheduler->now());
}

Simulation::Simulation(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation() = default;

Simulation Simulation::load_file(const std::string& path, const Options& options) {
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  try {
    impl->scenario = std::make_unique<scenario::Scenario>(scenario::load_scenario_file(path));
    impl->build();
  } catch (const scenario::LoadError& e) {
    rethrow(e);
  }
  return Simulation(std::move(impl));
}

Simulation Simulation::load_string(std::string_view yaml, const Options& options, const std::string& name,
                                   const std::string& dir) {
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  try {
    impl->scenario = std::make_unique<scenario::Scenario>(scenario::parse_scenario(std::string(yaml), name, dir));
    impl->build();
  } catch (const scenario::LoadError& e) {
    rethrow(e);
  }
  return Simulation(std::move(impl));
}

Endpoint& Simulation::attach(const std::string& bus, FrameHandler on_frame) {
  auto& m = *impl_;
  const int index = m.world->bus_index(bus);
  if (index < 0) fail("attach: the scenario has no bus '" + bus + "'");
  m.endpoints.push_back(std::make_unique<CallerEndpoint>(*m.world->buses()[static_cast<std::size_t>(index)],
                                                         *m.scheduler, std::move(on_frame)));
  return *m.endpoints.back();
}

void Simulation::add_step(StepFunction step) { impl_->caller_steps.add(std::move(step)); }

Time Simulation::now() const { return impl_->scheduler->now().time_since_epoch(); }
Duration Simulation::tick() const { return impl_->scheduler->tick(); }

void Simulation::run_for(Duration d) {
  const RunGuard guard(impl_->running, "run_for");
  auto& sched = *impl_->scheduler;
  if (d.count() > 0) sched.run_ticks(static_cast<std::uint64_t>((d.count() + sched.tick().count() - 1) / sched.tick().count()));
  impl_->flush();
}

bool Simulation::run_until(const std::function<bool()>& condition, Duration timeout) {
  const RunGuard guard(impl_->running, "run_until");
  auto& sched = *impl_->scheduler;
  const auto end = sched.now() + timeout;
  bool held = condition();
  while (!held && sched.now() < end) {
    sched.run_ticks(1);
    held = condition();
  }
  impl_->flush();
  return held;
}

double Simulation::signal(const std::string& expression) {
  auto& m = *impl_;
  auto it = m.signals.find(expression);
  if (it == m.signals.end()) {
    try {
      auto bound = m.world->resolve(scenario::parse_signal(expression, scenario::SourceMark{"<signal>", 1, 1}));
      it = m.signals.emplace(expression, std::move(bound)).first;
      for (std::size_t bus = 0; bus < m.last_frames.size(); ++bus)
        m.last_frames[bus]->replay(m.world->frame_fields(), static_cast<int>(bus));
    } catch (const scenario::LoadError& e) {
      rethrow(e);
    }
  }
  return it->second.value();
}

double Simulation::parameter(const std::string& name) const {
  auto* plant = impl_->world->plant();
  if (!plant) fail("parameter '" + name + "': the scenario has no plant");
  const auto v = plant->parameter(name);
  if (!v) fail("the plant has no parameter '" + name + "'; it has: " + list_parameters(*plant));
  return *v;
}

std::vector<std::uint8_t> Simulation::object(const std::string& node, std::uint16_t index, std::uint8_t sub) const {
  auto* n = impl_->world->find_node(node);
  if (!n) fail("object: no node '" + node + "'");
  const auto* entry = n->device->node().od().entry(index, sub);
  if (!entry) {
    char where[16];
    std::snprintf(where, sizeof where, "%04Xh:%02X", index, sub);
    fail("object: node '" + node + "' has no entry " + where);
  }
  return entry->value.bytes();
}

void Simulation::set_parameter(const std::string& name, double value) {
  auto* plant = impl_->world->plant();
  if (!plant) fail("parameter '" + name + "': the scenario has no plant");
  if (auto error = plant->set_parameter(name, value); !error.empty()) {
    if (!plant->parameter(name)) error += "; the plant's parameters are: " + list_parameters(*plant);
    fail(error);
  }
}

void Simulation::set_input(const std::string& node, const std::string& input, double value) {
  auto* n = impl_->world->find_node(node);
  if (!n) fail("set_input: no node '" + node + "'");
  if (auto error = n->device->set_input(input, value); !error.empty()) fail("set_input " + node + "." + input + ": " + error);
}

void Simulation::inject_fault(const std::string& yaml) {
  auto& m = *impl_;
  try {
    // The scenario's fault codec: the same syntax, checks and messages as a script's `fault:`.
    m.faults->inject(scenario::parse_fault(yaml, "<fault>"), m.scheduler->now());
  } catch (const scenario::LoadError& e) {
    rethrow(e);
  }
}

const std::vector<TimedFrame>& Simulation::trace() const { return impl_->recorder.frames; }
bool Simulation::script_finished() const { return impl_->master->finished(); }
std::size_t Simulation::assertions() const { return impl_->verdicts.outcomes().size(); }

std::vector<std::string> Simulation::failures() const {
  std::vector<std::string> lines;
  for (const auto& o : impl_->verdicts.outcomes()) {
    if (o.passed) continue;
    char time[32];
    std::snprintf(time, sizeof time, "%.3f", sim::seconds(o.time));
    lines.push_back(o.mark.to_string() + ": FAILED at " + time + " s: " + o.name + ": expected " + o.expected +
                    ", actual " + o.actual);
  }
  return lines;
}

}  // namespace vplant
