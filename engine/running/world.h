// The built machine of a scenario: buses (virtual or SocketCAN), devices from the registry with
// their parameter overrides, the plant, the wires, and signal lookup by name. Building checks
// everything the loader cannot: device types and settings, node-IDs per bus, object dictionary
// entries, port names and directions. Errors are LoadErrors at the scenario's line.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "devices/device.h"
#include "sim/bus.h"
#include "engine/running/environment.h"
#include "engine/running/random.h"
#include "engine/loading/scenario.h"
#include "engine/running/signal_source.h"
#include "engine/running/wiring.h"

namespace scenario {

struct BuildOptions {
  std::map<std::string, std::string> can;  ///< bus name → SocketCAN interface (overrides the file)
  bool strict_eds = false;                 ///< EDS nodes reject CiA 306 deviations (--strict)
};

struct NodeInstance {
  const NodeSpec* spec = nullptr;
  std::unique_ptr<devices::Device> device;
  sim::PortList ports;
  int bus = 0;  ///< index into World::buses
  std::uint8_t node_id = 0;
};

class World {
 public:
  /// Throws LoadError.
  World(const Scenario& scenario, const Environment& env, const BuildOptions& options, std::uint64_t seed);
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  const Scenario& scenario() const { return scenario_; }
  std::vector<std::unique_ptr<sim::Bus>>& buses() { return buses_; }
  /// Index of a bus by name ("" = the first); -1 if unknown.
  int bus_index(const std::string& name) const;
  std::vector<NodeInstance>& nodes() { return nodes_; }
  NodeInstance* find_node(const std::string& name);
  /// The in-process node with this node-ID on bus `bus`, or nullptr.
  NodeInstance* find_node(int bus, std::uint8_t node_id);
  PlantModel* plant() { return plant_.get(); }
  WireSet& plant_to_devices() { return plant_to_devices_; }
  WireSet& devices_to_plant() { return devices_to_plant_; }
  FrameFieldStore& frame_fields() { return frame_fields_; }
  Random& random() { return random_; }
  bool any_socketcan() const;
  /// What building found usable but doubtful (a deprecated device setting), as
  /// "file:line:col: warning: ..." lines; each is also printed to stderr when found.
  const std::vector<std::string>& warnings() const { return warnings_; }

  /// Binds a signal expression; throws LoadError at the expression's mark.
  Signal resolve(const SignalExpr& e);
  /// Every port named by a wire (both ends), for a CSV without an explicit signal list.
  std::vector<SignalExpr> wired_signals() const;

 private:
  struct PortRef {
    const sim::Port* port = nullptr;
    bool on_plant = false;
  };
  void build_buses(const BuildOptions& options);
  void build_nodes(const Environment& env, bool strict_eds);
  void build_plant(const Environment& env);
  void build_wires();
  PortRef find_port(const std::string& qualified, const SourceMark& mark) const;
  Signal resolve_term(const SignalExpr& e);
  Signal resolve_bus_signal(const SignalExpr& e);

  const Scenario& scenario_;
  Random random_;
  std::vector<std::unique_ptr<sim::Bus>> buses_;
  std::vector<NodeInstance> nodes_;
  std::vector<std::string> warnings_;
  std::unique_ptr<PlantModel> plant_;
  WireSet plant_to_devices_{&random_};
  WireSet devices_to_plant_{&random_};
  FrameFieldStore frame_fields_;
};

}  // namespace scenario
