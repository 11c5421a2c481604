// A scenario as data: what scenario_loader reads from YAML and the runner builds and runs.
// No behaviour here; docs/scenarios.md is the reference of every key.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "devices/canopen/nmt_state.h"
#include "sim/bus.h"
#include "sim/can_frame.h"
#include "sim/time.h"
#include "engine/loading/master_rules.h"
#include "engine/loading/condition.h"
#include "engine/loading/frame_pattern.h"
#include "engine/loading/signal_expression.h"
#include "engine/loading/source_mark.h"
#include "engine/loading/yaml_fields.h"

namespace scenario {

// ---- the machine --------------------------------------------------------------------------------

struct BusSpec {
  std::string name;
  std::string iface;  ///< "" = the in-process virtual bus; else a SocketCAN interface or a socketcand spec
  std::uint32_t bitrate = 500000;  ///< bit/s: the virtual bus times frames at this rate
  /// `bit` (default): the virtual bus gives every frame its bit time (sim::BusTiming::Bit);
  /// `ideal`: zero-time delivery. A SocketCAN bus is always ideal: the real wire times it.
  sim::BusTiming timing = sim::BusTiming::Bit;
  std::size_t tx_queue = sim::Bus::kDefaultTxQueue;  ///< per-endpoint transmit queue depth
  SourceMark mark;
};

/// An object-dictionary value the node's non-volatile memory holds at every power-on.
struct ParameterOverride {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  Literal value;
  SourceMark mark;
};

struct NodeSpec {
  std::string name;    ///< prefix of the node's signals: `<name>.<port>`
  std::string device;  ///< product name from the registry, or "eds"
  std::string variant;
  std::string eds;     ///< device "eds": the EDS file (relative to the scenario file)
  std::uint8_t node_id = 0;  ///< 0 = the product's default
  std::string bus;
  std::map<std::string, std::string> settings;
  std::vector<ParameterOverride> parameters;
  std::vector<std::pair<std::string, double>> inputs;  ///< constant input ports (Device::set_input)
  std::vector<SourceMark> input_marks;
  std::string store;   ///< non-volatile memory file (relative to the scenario file); "" = in memory
  SourceMark mark, device_mark, node_id_mark, settings_mark, store_mark;
};

struct WireSpec {
  std::string from, to;  ///< qualified port names
  double scale = 1.0;    ///< to = from * scale + offset (+ noise)
  double offset = 0.0;
  double noise = 0.0;    ///< standard deviation of Gaussian noise added each tick (seeded)
  SourceMark mark, from_mark, to_mark;
};

struct ClockSpec {
  enum class Mode { Auto, Virtual, RealTime } mode = Mode::Auto;  ///< Auto: real time iff a bus is on SocketCAN
  sim::Duration tick = sim::milliseconds(1);
  std::optional<sim::Duration> duration;
  std::uint64_t seed = 1;
  SourceMark mark;  ///< the `clock:` section, else the top-level mapping ("nothing ends this run")
};

// ---- outputs ------------------------------------------------------------------------------------

struct CsvSpec {
  std::string file;
  std::vector<SignalExpr> signals;  ///< empty = every wired port
};

/// One plot of the HTML report's case page (engine/reporting/html/).
struct PlotSpec {
  std::string title;
  std::string y_label;
  std::vector<SignalExpr> signals;
  std::vector<std::string> labels;  ///< legend text per signal ("" = the expression)
  SourceMark mark;
};

struct OutputSpec {
  std::string trace;  ///< candump -L log
  std::optional<CsvSpec> csv;
  sim::Duration sample_period = sim::milliseconds(10);  ///< CSV and the report's plots
  std::vector<PlotSpec> plots;
  std::string junit;
};

// ---- the live control plane ---------------------------------------------------------------------

/// `ui:` — serve the control plane (control/, docs/api.md) while the scenario runs. Data only: the
/// command line builds the server.
struct UiSpec {
  std::string listen;         ///< "[ADDR:]PORT"; "" = no control plane
  bool allow_remote = false;  ///< a non-loopback address needs it
  bool start_paused = true;   ///< virtual time: wait at t = 0 for the dashboard
  double speed = 1.0;         ///< virtual time: × wall clock while running (0 = as fast as possible)
  SourceMark mark;
};

// ---- faults -------------------------------------------------------------------------------------

struct WireFault {
  std::string bus;  ///< "" = first bus
  FramePattern match;
  /// TxError: every transmission attempt of `node` is destroyed by a bit error (error frame,
  /// fault confinement counters, automatic retransmission); `match` is not used.
  enum class Kind { Drop, Delay, Corrupt, TxError } kind = Kind::Drop;
  std::string node;   ///< TxError: the transmitting node
  int endpoint = -1;  ///< TxError: its endpoint on the bus (resolved when applied)
  sim::Duration delay{0};
  int byte = 0;              ///< Corrupt: which data byte
  std::uint8_t xor_mask = 0xFF;
  std::optional<std::uint8_t> set_value;  ///< Corrupt: replace instead of xor
  bool random_value = false;              ///< Corrupt: a random byte (seeded)
  double probability = 1.0;  ///< of each matching frame (seeded)
  std::uint64_t count = 0;   ///< frames affected at most (0 = unlimited)
};
struct BusOff {
  std::string node;
};
struct DeviceFault {
  std::string node;
  std::string fault;
  bool active = true;
};
struct Power {
  std::string node;
  enum class Kind { Off, On, Cycle, Reset } kind = Kind::Cycle;
  sim::Duration off_time{0};  ///< Cycle: how long the node stays off
};
struct PlantParameter {
  std::string name;  ///< component.parameter
  double value = 0;
};
using FaultAction = std::variant<WireFault, BusOff, DeviceFault, Power, PlantParameter>;

struct FaultSpec {
  FaultAction action;
  std::optional<sim::Duration> at;       ///< scheduled (absolute time)
  std::optional<Condition> when;         ///< on condition (first time it holds)
  std::optional<sim::Duration> duration; ///< cleared / restored after this long
  std::string name;
  SourceMark mark;
  std::string summary;  ///< one line for logs and reports
};

// ---- script -------------------------------------------------------------------------------------

/// A node as a script step addresses it: by scenario name (in-process) or by node-ID.
struct NodeRef {
  std::string name;        ///< "" when given by number
  std::uint8_t node_id = 0;  ///< 0 with empty name = all nodes (NMT only)
};

struct NmtStep {
  canopen::NmtCommand command = canopen::NmtCommand::Start;
  NodeRef node;
};
struct SyncStep {
  sim::Duration period{0};  ///< 0 = stop producing
  std::uint8_t counter_overflow = 0;  ///< 0 = no counter byte; 2..240 = counter
};
struct SdoTarget {
  NodeRef node;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::string type;  ///< "" = from the node's object dictionary
};
struct SdoReadStep {
  SdoTarget target;
  std::optional<Literal> expect;
  double tolerance = 0;
  std::optional<std::vector<std::uint8_t>> expect_data;
  std::optional<std::uint32_t> expect_abort;
  sim::Duration timeout = sim::milliseconds(1000);
};
struct SdoWriteStep {
  SdoTarget target;
  std::optional<Literal> value;
  std::optional<std::vector<std::uint8_t>> data;
  std::optional<std::uint32_t> expect_abort;
  sim::Duration timeout = sim::milliseconds(1000);
};
struct SendStep {
  sim::CanFrame frame;
};
struct RpdoStep {
  std::string node;
  int pdo = 1;
  std::vector<ParameterOverride> values;  ///< object → value
};
struct WaitStep {
  sim::Duration duration{0};
};
struct WaitFrameStep {
  FramePattern pattern;
  sim::Duration timeout{0};
};
struct WaitUntilStep {
  Condition condition;
  sim::Duration timeout{0};
};
struct ExpectStep {
  enum class Mode { Now, Within, During, UntilEnd, Slope } mode = Mode::Now;
  Condition condition;     ///< Slope: signal; a = slope, b = tolerance
  sim::Duration window{0};
};
struct ExpectFramesStep {
  FramePattern select;
  std::optional<FramePattern> content;  ///< data every selected frame must have
  sim::Duration window{0};
  std::optional<std::uint64_t> min_count, max_count;
  std::optional<sim::Duration> period;
  sim::Duration period_tolerance{0};
};
struct FaultStep {
  FaultSpec fault;
};
struct LogStep {
  std::string message;
};

using StepAction = std::variant<NmtStep, SyncStep, SdoReadStep, SdoWriteStep, SendStep, RpdoStep, WaitStep,
                                WaitFrameStep, WaitUntilStep, ExpectStep, ExpectFramesStep, FaultStep, LogStep>;

struct Step {
  StepAction action;
  std::optional<sim::Duration> at;  ///< do not start before this absolute time
  std::string name;                 ///< for reports ("" = generated from the action)
  std::string bus;                  ///< bus it sends on / observes ("" = default)
  SourceMark mark;
  std::string summary;              ///< e.g. "sdo_write dsv 0x6040:00 = 15"
};

// ---- the whole scenario -------------------------------------------------------------------------

struct Scenario {
  std::string file;  ///< as given
  std::string dir;   ///< directory of the file (for relative input paths)
  std::string name;
  std::string description;
  std::vector<BusSpec> buses;
  std::vector<NodeSpec> nodes;
  bool has_plant = false;
  YAML::Node plant;  ///< the `plant:` section as written
  SourceMark plant_mark;
  std::vector<WireSpec> wires;
  ClockSpec clock;
  OutputSpec outputs;
  std::vector<Step> script;
  std::vector<FaultSpec> faults;
  UiSpec ui;
  MasterRuleSettings master_rules;  ///< `master_rules:` severities of the master monitor's rules
};

}  // namespace scenario
