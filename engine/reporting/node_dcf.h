// `vplant dcf SCENARIO NODE`: the CiA 306 DCF of one node of a scenario, as the scenario
// configures it: variant, settings, `parameters:` overrides (applied at power-on like the node's
// non-volatile memory), its store file, and its node-ID and bus. A master configures its PDOs
// from this file and gets the mapping the running node has.
#pragma once

#include <string>

#include "engine/running/environment.h"
#include "engine/loading/scenario.h"

namespace scenario {

/// The node's DCF. The scenario's buses are built as virtual buses (nothing is opened). Throws
/// LoadError for a scenario that cannot be built or an unknown node.
std::string node_dcf(Scenario scenario, const Environment& env, const std::string& node_name);

}  // namespace scenario
