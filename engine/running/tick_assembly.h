// The order in which one tick steps the run's components, written once: `vplant run`
// (engine/runner.cpp), the library (api/simulation.cpp) and, through the runner, the live control
// plane all assemble their scheduler here (docs/architecture.md, "One tick").
#pragma once

#include <string_view>
#include <vector>

namespace sim {
class Scheduler;
class Steppable;
}  // namespace sim

namespace scenario {

class World;
class FaultInjector;
class ScriptedMaster;
class NodeGroup;

/// What one run steps each tick. The optional parts are left out when null.
struct TickParts {
  World& world;
  FaultInjector& faults;
  ScriptedMaster& master;
  NodeGroup& nodes;
  sim::Steppable* caller_steps = nullptr;  ///< the library's step functions (Simulation::add_step)
  sim::Steppable* monitor = nullptr;       ///< the verdict on the master (engine/running/master_monitor.h)
  sim::Steppable* recorder = nullptr;      ///< the CLI's CSV and plot samples
};

struct TickComponent {
  std::string_view name;
  sim::Steppable* component;
};

/// The components in the order they step: faults, master, caller steps, plant → devices, nodes,
/// master monitor, devices → plant, recorder, plant (absent parts left out).
std::vector<TickComponent> tick_components(const TickParts& parts);

/// Adds the world's buses and tick_components(parts), in that order, to `scheduler`.
void assemble_tick(sim::Scheduler& scheduler, const TickParts& parts);

}  // namespace scenario
