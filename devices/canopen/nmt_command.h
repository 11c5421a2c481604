// The NMT command words, the same in every front door: a scenario's `nmt:` step, the HTTP API's
// POST /api/nmt, the dashboard's buttons and the frame decoder's text.
#pragma once

#include <optional>
#include <string_view>

#include "devices/canopen/nmt_state.h"

namespace canopen {

/// start, stop, pre_operational, reset_node, reset_communication.
std::string_view to_string(NmtCommand c);
/// The command for its word; nullopt for any other text.
std::optional<NmtCommand> parse_nmt_command(std::string_view word);
/// The words, for messages: "start, stop, pre_operational, reset_node or reset_communication".
inline constexpr std::string_view kNmtCommandWords = "start, stop, pre_operational, reset_node or reset_communication";

}  // namespace canopen
