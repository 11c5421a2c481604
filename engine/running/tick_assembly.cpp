#include "engine/running/tick_assembly.h"

#include "engine/running/fault_injector.h"
#include "engine/running/node_group.h"
#include "engine/running/scripted_master.h"
#include "engine/running/world.h"
#include "sim/scheduler.h"

namespace scenario {

std::vector<TickComponent> tick_components(const TickParts& p) {
  std::vector<TickComponent> order;
  // Faults first: a rule that starts at `now` holds for everything this tick sends. The master
  // then acts on the state the last tick left; the caller's steps act like a second master.
  order.push_back({"faults", &p.faults});
  order.push_back({"master", &p.master});
  if (p.caller_steps) order.push_back({"caller steps", p.caller_steps});
  // Sensors read the plant at `now`, the nodes step, their outputs drive the plant.
  order.push_back({"plant -> devices", &p.world.plant_to_devices()});
  order.push_back({"nodes", &p.nodes});
  // The monitor judges the master by the frames and node states the tick has produced so far.
  if (p.monitor) order.push_back({"master monitor", p.monitor});
  order.push_back({"devices -> plant", &p.world.devices_to_plant()});
  // The recorder samples at `now`, before the plant integrates over [now, now + dt].
  if (p.recorder) order.push_back({"recorder", p.recorder});
  if (p.world.plant()) order.push_back({"plant", p.world.plant()});
  return order;
}

void assemble_tick(sim::Scheduler& scheduler, const TickParts& parts) {
  for (auto& bus : parts.world.buses()) scheduler.add_bus(bus.get());
  for (const auto& c : tick_components(parts)) scheduler.add(c.component);
}

}  // namespace scenario
