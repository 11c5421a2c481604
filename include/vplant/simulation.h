// vplant public API: a whole virtual plant in the caller's process, in virtual time.
//
//   vplant::Simulation sim = vplant::Simulation::load_file("reference-plant.yaml");
//   vplant::Endpoint& bus = sim.attach("main", [&](const vplant::Frame& f, vplant::Time t) { ... });
//   sim.add_step([&](vplant::Time now, vplant::Duration tick) { bus.send(...); });
//   sim.run_until([&] { return sim.signal("cyl.position") > 0.2; }, 5s);
//   double bore = sim.parameter("cyl.bore_diameter");
//
// One tick (the scenario's clock.tick, default 1 ms): scenario faults, the scenario's scripted
// master (Options::run_script), the caller's step functions in the order added, then the nodes and
// the plant (docs/architecture.md, "One tick"). Frames are delivered after every component, so an
// answer reaches the caller's endpoint in the tick its request was sent. Everything runs on the
// calling thread; the same scenario, seed and caller code give the same trace every time.
// docs/embedding.md is the guide.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <vplant/error.h>
#include <vplant/frame.h>

namespace vplant {

struct Options {
  /// Run the scenario's own `script:` (its scripted master and assertions) beside the caller's
  /// code. Off by default: the caller is the master; the file's script and clock.duration are
  /// dropped (like `vplant run --no-script`).
  bool run_script = false;
  /// Overrides clock.seed (noise, random faults).
  std::optional<std::uint64_t> seed;
  /// Keep every frame for trace(). Memory grows with the run (about 40 bytes a frame).
  bool record_trace = true;
  /// Also write every frame to this file in `candump -L` format ("" = no file).
  std::string trace_file;
};

/// The caller's own endpoint on a bus: it receives every frame other endpoints send (through the
/// handler given to attach) and sends frames as a node on that bus would.
class Endpoint {
 public:
  virtual ~Endpoint() = default;
  /// Queues a frame; it is delivered within the current tick (from a step or a frame handler),
  /// or at the start of the next tick (between runs). Throws Error for a frame classic CAN cannot
  /// carry (DLC above 8, an identifier beyond 7FFh or, extended, 1FFFFFFFh).
  virtual void send(const Frame& frame) = 0;
  virtual const std::string& bus() const = 0;
};

class Simulation {
 public:
  using FrameHandler = std::function<void(const Frame& frame, Time now)>;
  using StepFunction = std::function<void(Time now, Duration tick)>;

  /// Loads and builds a scenario (docs/scenarios.md). Throws Error (`file:line:col: reason`).
  /// Buses must be in-process (`transport: virtual`) and the clock virtual: the library does not
  /// run in real time.
  static Simulation load_file(const std::string& path, const Options& options = {});
  /// The same from YAML text; `name` stands for the file in errors, relative paths (EDS files,
  /// parameter stores) resolve against `dir`.
  static Simulation load_string(std::string_view yaml, const Options& options = {}, const std::string& name = "<string>",
                                const std::string& dir = ".");

  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;
  ~Simulation();

  /// Attaches an endpoint to bus `bus` ("" = the scenario's first bus); the simulation owns it.
  /// Throws Error for an unknown bus. `on_frame` may send (the answer goes out in the same tick).
  Endpoint& attach(const std::string& bus, FrameHandler on_frame);
  /// Runs `step` every tick, after the scenario's faults and scripted master, before the nodes.
  void add_step(StepFunction step);

  Time now() const;
  Duration tick() const;
  /// Advances simulated time by `d` (rounded up to whole ticks). run_for and run_until are for the
  /// caller's code: called from a step function or frame handler (inside a run) they throw Error.
  void run_for(Duration d);
  /// Runs tick by tick until `condition` holds (checked before each tick) or `timeout` of
  /// simulated time has passed; returns whether it held.
  bool run_until(const std::function<bool()>& condition, Duration timeout);

  /// The value of a signal expression (docs/scenarios.md, "Signals"): a plant port
  /// (`cyl.position`), a node's port (`dsv.solenoid_a_current`), `hlt.nmt_state`, a frame field
  /// (`frame(0x285)[0:4] as i32 * 1e-4`, NaN before the first such frame), sums and scales of
  /// these. SI units. Throws Error for an unknown name or a malformed expression.
  double signal(const std::string& expression);
  /// A run-time parameter of the plant, "component.parameter" (e.g. "cyl.bore_diameter"). Throws
  /// Error for an unknown one, listing the plant's parameters.
  double parameter(const std::string& name) const;
  /// The stored value of entry index:sub of node `node` (its scenario name), little-endian. No
  /// SDO, no read hooks, no time passes: a value the device computes when read may be stale (read
  /// it with test::SdoClient as a master would). Throws Error for an unknown node or entry.
  std::vector<std::uint8_t> object(const std::string& node, std::uint16_t index, std::uint8_t sub) const;
  /// Changes a plant parameter between ticks (the plant's range checks apply). Throws Error.
  void set_parameter(const std::string& name, double value);
  /// Sets a node's input port or run-time quantity (Device::set_input, e.g. "hlt", "position").
  /// Throws Error for an unknown node or input.
  void set_input(const std::string& node, const std::string& input, double value);
  /// Applies a fault now, written as a step of a scenario's script would write it
  /// (docs/scenarios.md, "Faults"), e.g. `{device_fault: {node: hlt, fault: magnet_lost}, for: 200ms}`
  /// or `{drop: {id: 0x285}}`; JSON too, as the HTTP API's POST /api/faults takes it. Throws Error
  /// (`<fault>:line:col: reason`) for a malformed fault and for one its node or plant refuses.
  void inject_fault(const std::string& yaml);

  /// Every frame delivered so far, in order (Options::record_trace).
  const std::vector<TimedFrame>& trace() const;
  /// Options::run_script: the script has run to its end and no assertion is pending.
  bool script_finished() const;
  /// The scenario's assertions decided so far that failed, as `vplant run` prints them
  /// (`file:line:col: FAILED at 1.234 s: name: expected ..., actual ...`).
  std::vector<std::string> failures() const;
  /// The number of assertions decided so far (passed and failed).
  std::size_t assertions() const;

 private:
  struct Impl;
  explicit Simulation(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vplant
