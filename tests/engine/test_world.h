// Small stand-ins for the engine tests: an "axis" product (a CANopen node that reports a position
// by TPDO1 on SYNC and takes a velocity command by RPDO1) and an "axis" plant (an integrator with
// a gain and a drift parameter). They exercise every path of the engine without the real
// products and physics.
#pragma once

#include <memory>
#include <string>

#include "engine/running/environment.h"

namespace vtest {

/// The test environment: product "axis" (plus the registry's), plant section `axis: {gain, drift}`.
scenario::Environment test_environment();

/// One axis node (ID 5) wired to the axis plant: the start of most engine tests' scenarios.
inline const std::string kMachine = R"(
nodes:
  - {name: ax, device: axis, node_id: 5}
plant:
  axis: {gain: 1.0}
wires:
  - {from: ax.velocity, to: axis.velocity_command}
  - {from: axis.position, to: ax.position}
)";

}  // namespace vtest
