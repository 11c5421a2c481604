#include "devices/canopen/nmt_command.h"

namespace canopen {

std::string_view to_string(NmtCommand c) {
  switch (c) {
    case NmtCommand::Start: return "start";
    case NmtCommand::Stop: return "stop";
    case NmtCommand::EnterPreOperational: return "pre_operational";
    case NmtCommand::ResetNode: return "reset_node";
    case NmtCommand::ResetCommunication: return "reset_communication";
  }
  return "unknown";
}

std::optional<NmtCommand> parse_nmt_command(std::string_view word) {
  for (const auto c : {NmtCommand::Start, NmtCommand::Stop, NmtCommand::EnterPreOperational, NmtCommand::ResetNode,
                       NmtCommand::ResetCommunication})
    if (to_string(c) == word) return c;
  return std::nullopt;
}

}  // namespace canopen
