// Steps every node of a world in scenario order: one scheduler component for all of them (used
// by the runner and by the library's Simulation).
#pragma once

#include <vector>

#include "devices/canopen/node.h"
#include "sim/scheduler.h"
#include "sim/tick_profile.h"
#include "engine/running/world.h"

namespace scenario {

class NodeGroup final : public sim::Steppable {
 public:
  explicit NodeGroup(World& world) {
    for (auto& n : world.nodes()) nodes_.push_back(&n.device->node());
  }
  void step(sim::Time now, sim::Duration dt) override {
    const sim::TickProbe probe(sim::TickPart::Nodes);
    for (auto* n : nodes_) n->step(now, dt);
  }

 private:
  std::vector<canopen::Node*> nodes_;
};

}  // namespace scenario
