// `vplant node`: one emulated node on a SocketCAN interface or the virtual bus, in real time
// (a master under test talks to it) or in virtual time for a fixed duration.
#include <atomic>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "control/control_plane.h"
#include "devices/canopen/parameter_store.h"
#include "devices/generic/eds_node.h"
#include "engine/runner.h"
#include "devices/registry.h"
#include "sim/bus.h"
#include "sim/log.h"
#include "sim/realtime_setup.h"
#include "sim/scheduler.h"
#include "sim/transport_factory.h"
#include "sim/trace_writer.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exit_codes.h"
#include "tools/vplant/key_value.h"
#include "tools/vplant/stop_signals.h"

namespace vplant {

namespace {

std::atomic<sim::Scheduler*> g_running{nullptr};
std::atomic<scenario::Runner*> g_runner{nullptr};  // --ui: the node runs as a one-node scenario

bool stop_running_node() {
  if (sim::Scheduler* s = g_running.load()) {
    s->request_stop();
    return true;
  }
  if (scenario::Runner* r = g_runner.load()) {
    r->request_stop();
    return true;
  }
  return false;
}

struct NodeOptions {
  std::string eds;
  std::string device;
  std::string variant;
  int node_id = 0;
  std::string can;
  std::vector<std::string> inputs;
  std::vector<std::string> settings;
  std::string store;
  double duration_s = 0;
  std::string trace;
  bool virtual_time = false;
  std::string ui;
  bool ui_allow_remote = false;
  bool strict = false;
  bool rt = false;
};

/// `--ui`: the node runs as a one-node scenario (bus "main"), so the control plane sees it as it
/// sees any run (docs/api.md).
int run_node_with_ui(const NodeOptions& o, const std::map<std::string, std::string>& settings,
                     const std::map<std::string, double>& inputs) {
  control::UiOptions u;
  if (auto err = control::parse_ui_address(o.ui, u); !err.empty()) {
    std::fprintf(stderr, "vplant node: --ui %s\n", err.c_str());
    return kExitBadInput;
  }
  if (o.trace == "-") {
    std::fprintf(stderr, "vplant node: --trace - (stdout) cannot be combined with --ui; give a file\n");
    return kExitBadInput;
  }
  u.allow_remote = o.ui_allow_remote;
  scenario::Scenario s;
  s.file = "vplant node";
  s.dir = ".";
  s.name = o.eds.empty() ? o.device : o.eds;
  scenario::BusSpec bus;
  bus.name = "main";
  bus.iface = o.can;
  s.buses.push_back(bus);
  scenario::NodeSpec n;
  n.name = o.eds.empty() ? o.device : "node";
  n.device = o.eds.empty() ? o.device : "eds";
  n.eds = o.eds;
  n.variant = o.variant;
  n.node_id = static_cast<std::uint8_t>(o.node_id);
  n.bus = "main";
  n.settings = settings;
  n.store = o.store;
  for (const auto& [name, value] : inputs) {
    n.inputs.emplace_back(name, value);
    n.input_marks.push_back(scenario::SourceMark{"--set", 0, 0});
  }
  s.nodes.push_back(std::move(n));
  s.clock.mode = o.virtual_time ? scenario::ClockSpec::Mode::Virtual : scenario::ClockSpec::Mode::RealTime;
  if (o.duration_s > 0) s.clock.duration = sim::from_seconds(o.duration_s);
  auto plane = std::make_unique<control::ControlPlane>(u);
  if (auto err = plane->bind(); !err.empty()) {
    std::fprintf(stderr, "vplant node: %s\n", err.c_str());
    return kExitBadInput;
  }
  scenario::RunOptions ro;
  ro.trace = o.trace;
  ro.extension = plane.get();
  ro.strict_eds = o.strict;
  ro.rt = o.rt;
  try {
    scenario::Runner runner(s, scenario::default_environment(), ro);
    g_runner.store(&runner);
    const int rc = runner.run();
    g_runner.store(nullptr);
    return rc == 0 ? kExitOk : kExitBadInput;
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "vplant node: %s\n", e.what());
    return kExitBadInput;
  }
}

int run_node(const NodeOptions& o) {
  install_stop_signals(stop_running_node);
  if (o.eds.empty() == o.device.empty()) {
    std::fprintf(stderr, "vplant node: give exactly one of --eds FILE or --device NAME\n");
    return kExitBadInput;
  }
  if (o.virtual_time && o.duration_s <= 0 && o.ui.empty()) {
    std::fprintf(stderr, "vplant node: --virtual needs --duration\n");
    return kExitBadInput;
  }
  devices::DeviceOptions options;
  options.node_id = static_cast<std::uint8_t>(o.node_id);
  options.variant = o.variant;
  options.store_path = o.store;
  options.strict_eds = o.strict;
  std::string error;
  if (!o.store.empty()) {
    // Read again at power-on; reading it now turns a bad file into exit 2 before anything runs.
    canopen::ParameterStore probe(o.store);
    if (!probe.load(error)) {
      std::fprintf(stderr, "vplant node: --store %s\n", error.c_str());
      return kExitBadInput;
    }
  }
  if (!parse_key_values(o.settings, options.settings, error)) {
    std::fprintf(stderr, "vplant node: --setting %s\n", error.c_str());
    return kExitBadInput;
  }
  std::map<std::string, double> inputs;
  if (!parse_key_numbers(o.inputs, inputs, error)) {
    std::fprintf(stderr, "vplant node: --set %s\n", error.c_str());
    return kExitBadInput;
  }

  if (!o.ui.empty()) return run_node_with_ui(o, options.settings, inputs);

  std::unique_ptr<devices::Device> device;
  if (!o.eds.empty()) {
    device = devices::EdsNode::load(o.eds, options, error);
  } else if (const auto* product = devices::find_product(o.device)) {
    std::vector<std::string> warnings;
    options.warnings = &warnings;
    device = product->make(options, error);
    for (const auto& w : warnings) std::fprintf(stderr, "vplant node: --setting: warning: %s\n", w.c_str());
    options.warnings = nullptr;
  } else {
    error = "unknown device '" + o.device + "' (see `vplant devices`)";
  }
  if (!device) {
    std::fprintf(stderr, "vplant node: %s\n", error.c_str());
    return kExitBadInput;
  }
  for (const auto& [name, value] : inputs) {
    if (auto e = device->set_input(name, value); !e.empty()) {
      std::fprintf(stderr, "vplant node: --set %s\n", e.c_str());
      return kExitBadInput;
    }
  }

  // A socketcand bus is named `main` (the channel clients open, unless the spec names one).
  sim::Bus bus(o.can.empty() ? "virtual" : sim::is_socketcand_spec(o.can) ? "main" : o.can);
  if (!o.can.empty()) {
    auto transport = sim::open_transport(bus.name(), o.can, error);
    if (!transport) {
      std::fprintf(stderr, "vplant node: %s\n", error.c_str());
      return kExitBadInput;
    }
    bus.set_transport(std::move(transport));
  }
  std::unique_ptr<sim::TraceWriter> trace;
  if (!o.trace.empty()) {
    trace = o.trace == "-" ? std::make_unique<sim::TraceWriter>(stdout) : std::make_unique<sim::TraceWriter>(o.trace, error);
    if (!trace->is_open()) {
      std::fprintf(stderr, "vplant node: %s\n", error.c_str());
      return kExitBadInput;
    }
    if (!o.virtual_time) trace->set_epoch_offset(static_cast<std::int64_t>(std::time(nullptr)));
    bus.add_tap(trace.get());
  }

  sim::Scheduler scheduler(sim::milliseconds(1), o.virtual_time ? sim::ClockMode::Virtual : sim::ClockMode::RealTime);
  scheduler.add_bus(&bus);
  device->node().attach(bus);
  scheduler.add(&device->node());
  g_running.store(&scheduler);

  std::fprintf(stderr, "vplant node: %s node-ID %u on %s%s\n", o.eds.empty() ? o.device.c_str() : o.eds.c_str(),
               device->node().node_id(), o.can.empty() ? "the virtual bus" : o.can.c_str(),
               o.duration_s > 0 ? "" : " (Ctrl-C stops)");
  device->power_on(scheduler.now());
  if (o.rt) {
    std::string note = o.virtual_time ? "real time: --rt ignored: --virtual" : sim::enter_realtime().message;
    for (auto at = note.find('\n'); at != std::string::npos; at = note.find('\n', at + 1)) note.insert(at + 1, "vplant node: ");
    std::fprintf(stderr, "vplant node: %s\n", note.c_str());
  }
  if (o.duration_s > 0) {
    scheduler.run_for(sim::from_seconds(o.duration_s));
  } else {
    scheduler.run_until_stopped();
  }
  g_running.store(nullptr);
  const std::string trace_error = trace ? trace->close() : std::string();

  const auto& st = scheduler.stats();
  std::fprintf(stderr, "vplant node: %.3f s simulated, %llu frames on the bus", sim::seconds(scheduler.now()),
               static_cast<unsigned long long>(bus.stats().frames));
  if (scheduler.mode() == sim::ClockMode::RealTime) {
    std::fprintf(stderr, ", %llu overruns, worst tick lateness %lld us", static_cast<unsigned long long>(st.overruns),
                 static_cast<long long>(st.max_lateness.count()));
    if (st.reanchors)
      std::fprintf(stderr, " (schedule re-anchored %llu times: simulated time %.1f ms behind the wall clock)",
                   static_cast<unsigned long long>(st.reanchors), static_cast<double>(st.slipped.count()) / 1000.0);
  }
  if (bus.transport()) {
    const auto& ts = bus.transport()->stats();
    std::fprintf(stderr, ", tx busy %llu, tx dropped %llu", static_cast<unsigned long long>(ts.tx_busy),
                 static_cast<unsigned long long>(ts.tx_dropped));
  }
  std::fprintf(stderr, "\n");
  if (!trace_error.empty()) {
    std::fprintf(stderr, "vplant node: %s\n", trace_error.c_str());
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

Runner add_node_command(CLI::App& app) {
  auto o = std::make_shared<NodeOptions>();
  app.add_option("--eds", o->eds, "EDS file: any CiA 306 device becomes an emulated node");
  app.add_option("--device", o->device, "emulated product (see `vplant devices`)");
  app.add_option("--variant", o->variant, "product variant");
  app.add_option("--node-id", o->node_id, "node-ID (default: the product's factory setting)")->check(CLI::Range(1, 127));
  app.add_option("--can", o->can, "SocketCAN interface, socketcand:ADDR:PORT[/CHANNEL] or socketcand-client:HOST:PORT/CHANNEL (default: the in-process virtual bus)");
  app.add_option("--set", o->inputs, "input=value: hold a device input (e.g. actual=0.5, position=0.1)");
  app.add_option("--setting", o->settings, "knob=value: a product configuration setting (see docs/devices)");
  app.add_option("--store", o->store, "file for the node's non-volatile memory (0x1010 save)");
  app.add_option("--duration", o->duration_s, "seconds to run (default: until SIGINT/SIGTERM)")->check(CLI::NonNegativeNumber);
  app.add_option("--trace", o->trace, "write all frames in candump -L format ('-' = stdout)");
  app.add_flag("--virtual", o->virtual_time, "virtual time (as fast as possible; needs --duration unless --ui)");
  app.add_option("--ui", o->ui, "[ADDR:]PORT: serve the live control plane (docs/api.md); virtual time starts paused");
  app.add_flag("--ui-allow-remote", o->ui_allow_remote, "allow --ui on a non-loopback address (no authentication!)");
  app.add_flag("--rt", o->rt,
               "real time: run the scheduler's thread SCHED_FIFO (priority 49) with memory locked, where permitted");
  app.add_flag("--strict", o->strict, "--eds: reject the CiA 306 deviations that are otherwise loaded with a warning");
  return [o] { return run_node(*o); };
}

}  // namespace vplant
