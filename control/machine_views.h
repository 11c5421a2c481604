// The JSON of a node's state machines (docs/api.md "State machines"): its transition history
// (`GET /api/nodes/{name}/transitions`, the stream's `transition` event) and their descriptions
// with the state each is in now (`GET /api/nodes/{name}/machines`). The devices record and
// describe; this only writes it down.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "devices/device.h"
#include "devices/transition_log.h"

namespace control {

/// {"seq", "t_us", "machine", "from", "to", "transition", "cause", "value", "detail", "evidence"}.
nlohmann::json transition_json(const devices::Transition& t);

/// The entries of `log` after `after`, oldest first. Copies (no JSON): call it between ticks.
std::vector<devices::Transition> transitions_after(const devices::TransitionLog& log, std::uint64_t after);

/// {"node", "powered", "machines": [{"machine", "title", "state", "states", "edges", "note"}]}.
nlohmann::json machines_json(const std::string& node, bool powered, const std::vector<devices::MachineView>& machines);

}  // namespace control
