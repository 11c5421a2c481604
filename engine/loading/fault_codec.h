// The one reader of a fault: a scenario's `faults:` entry and `fault:` script step, the HTTP API's
// POST /api/faults body and vplant::Simulation::inject_fault all go through it, so a fault is
// written the same everywhere (docs/scenarios.md, "Faults"). JSON is read as YAML (it is a subset),
// so a JSON body gets the same checks and the same `<name>:line:col: reason` errors.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>

#include "engine/loading/scenario.h"

namespace scenario {

/// When the fault happens: `Scheduled` takes `at:` or `when:` (a `faults:` entry); `Now` takes
/// neither (a script step, or a fault injected into a running plant).
enum class FaultTiming { Scheduled, Now };

/// One fault: its action (drop, delay, corrupt, tx_errors, bus_off, device_fault, power_off,
/// power_on, power_cycle, reset, plant) and optional `name` and `for`. Throws LoadError in `file`.
FaultSpec read_fault(const YAML::Node& node, const std::string& file, FaultTiming timing);

/// One fault (FaultTiming::Now) from YAML or JSON text; errors name the text `name`.
FaultSpec parse_fault(std::string_view text, const std::string& name);

}  // namespace scenario
