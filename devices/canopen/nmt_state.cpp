#include "devices/canopen/nmt_state.h"

namespace canopen {

std::string_view to_string(NmtState s) {
  switch (s) {
    case NmtState::Initialising: return "INITIALISING";
    case NmtState::Stopped: return "STOPPED";
    case NmtState::Operational: return "OPERATIONAL";
    case NmtState::PreOperational: return "PRE-OPERATIONAL";
  }
  return "UNKNOWN";
}

}  // namespace canopen
