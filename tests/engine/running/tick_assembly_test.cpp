// The one tick order (engine/running/tick_assembly.h) that the CLI, the library and the control plane
// share, and that docs/architecture.md ("One tick") shows.
#include "engine/running/tick_assembly.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/engine/test_world.h"
#include "engine/running/fault_injector.h"
#include "engine/running/node_group.h"
#include "engine/running/outcome.h"
#include "engine/loading/scenario_loader.h"
#include "engine/running/scripted_master.h"
#include "engine/running/world.h"
#include "sim/scheduler.h"

namespace {

class Noop final : public sim::Steppable {
 public:
  void step(sim::Time, sim::Duration) override {}
};

struct Machine {
  explicit Machine(const std::string& yaml)
      : spec(scenario::parse_scenario(yaml, "test.yaml", ".")),
        world(spec, vtest::test_environment(), scenario::BuildOptions{}, 1),
        faults(world, verdicts, quiet),
        master(world, faults, verdicts, quiet),
        nodes(world) {}
  std::vector<std::string> names(sim::Steppable* caller_steps, sim::Steppable* recorder,
                                 sim::Steppable* monitor = nullptr) {
    std::vector<std::string> out;
    for (const auto& c : scenario::tick_components({world, faults, master, nodes, caller_steps, monitor, recorder}))
      out.emplace_back(c.name);
    return out;
  }
  static void quiet(sim::Time, const std::string&) {}
  scenario::Scenario spec;
  scenario::Verdicts verdicts;
  scenario::World world;
  scenario::FaultInjector faults;
  scenario::ScriptedMaster master;
  scenario::NodeGroup nodes;
};

using Names = std::vector<std::string>;

TEST(TickAssembly, TheCommandLineRunStepsFaultsMasterWiringNodesMonitorRecorderPlant) {
  Machine m(vtest::kMachine);
  Noop recorder, monitor;
  EXPECT_EQ(m.names(nullptr, &recorder, &monitor), (Names{"faults", "master", "plant -> devices", "nodes", "master monitor",
                                                          "devices -> plant", "recorder", "plant"}));
}

TEST(TickAssembly, TheLibraryStepsTheCallersFunctionsAfterTheMaster) {
  Machine m(vtest::kMachine);
  Noop steps;
  EXPECT_EQ(m.names(&steps, nullptr),
            (Names{"faults", "master", "caller steps", "plant -> devices", "nodes", "devices -> plant", "plant"}));
}

TEST(TickAssembly, BothOptionalPartsTakeTheirPlaces) {
  Machine m(vtest::kMachine);
  Noop steps, recorder;
  EXPECT_EQ(m.names(&steps, &recorder), (Names{"faults", "master", "caller steps", "plant -> devices", "nodes",
                                               "devices -> plant", "recorder", "plant"}));
}

TEST(TickAssembly, AWorldWithoutPlantHasNoPlantStep) {
  Machine m("nodes:\n  - {name: ax, device: axis, node_id: 5}\n");
  EXPECT_EQ(m.names(nullptr, nullptr), (Names{"faults", "master", "plant -> devices", "nodes", "devices -> plant"}));
}

TEST(TickAssembly, TheComponentsAreTheRunsOwnObjectsInTheSchedulersOrder) {
  Machine m(vtest::kMachine);
  Noop steps, recorder;
  const auto order = scenario::tick_components({m.world, m.faults, m.master, m.nodes, &steps, nullptr, &recorder});
  ASSERT_EQ(order.size(), 8u);
  EXPECT_EQ(order[0].component, &m.faults);
  EXPECT_EQ(order[1].component, &m.master);
  EXPECT_EQ(order[2].component, &steps);
  EXPECT_EQ(order[3].component, &m.world.plant_to_devices());
  EXPECT_EQ(order[4].component, &m.nodes);
  EXPECT_EQ(order[5].component, &m.world.devices_to_plant());
  EXPECT_EQ(order[6].component, &recorder);
  EXPECT_EQ(order[7].component, m.world.plant());
}

}  // namespace
