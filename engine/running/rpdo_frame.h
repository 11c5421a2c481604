// An RPDO as a master builds it from object values: the node's RPDO n as the node holds it now
// (1400h+n-1 COB-ID, 1600h+n-1 mapping), each mapped object's value encoded at its place. The
// scripted master's `rpdo` step and the control plane's POST /api/nodes/{name}/rpdo both use it.
#pragma once

#include <optional>
#include <span>
#include <string>

#include "devices/canopen/object_dictionary.h"
#include "engine/loading/scenario.h"
#include "sim/can_frame.h"

namespace scenario {

struct RpdoFrame {
  std::optional<sim::CanFrame> frame;  ///< the RPDO, when it could be built
  /// Else why not, as an expectation and what was found (e.g. "a value for every mapped object",
  /// "0x6040:00 is mapped but not given").
  std::string expected, actual;
  /// The value the problem is about (index into `values`), when it is one.
  std::optional<std::size_t> value;
};

/// Builds RPDO `pdo` (1-based) of the node whose dictionary is `od` from `values` (one per mapped
/// object, dummy entries excepted; each must be mapped). `node` names the node in the reasons.
RpdoFrame build_rpdo(const canopen::ObjectDictionary& od, std::string_view node, int pdo,
                     std::span<const ParameterOverride> values);

}  // namespace scenario
