// NMT states and commands (CiA 301 §7.3.2). The state values are the ones heartbeat and node
// guarding report.
#pragma once

#include <cstdint>
#include <string_view>

namespace canopen {

enum class NmtState : std::uint8_t {
  Initialising = 0x00,
  Stopped = 0x04,
  Operational = 0x05,
  PreOperational = 0x7F,
};

enum class NmtCommand : std::uint8_t {
  Start = 0x01,
  Stop = 0x02,
  EnterPreOperational = 0x80,
  ResetNode = 0x81,
  ResetCommunication = 0x82,
};

/// Communication errors that CiA 301 object 0x1029:01 reacts to.
enum class CommError : std::uint8_t { LifeGuarding, HeartbeatConsumer, BusOffRecovered };

std::string_view to_string(NmtState s);

/// Which services run in a state (CiA 301 table 48).
inline bool sdo_allowed(NmtState s) { return s == NmtState::PreOperational || s == NmtState::Operational; }
inline bool pdo_allowed(NmtState s) { return s == NmtState::Operational; }
inline bool emcy_allowed(NmtState s) { return s == NmtState::PreOperational || s == NmtState::Operational; }
inline bool sync_allowed(NmtState s) { return s == NmtState::PreOperational || s == NmtState::Operational; }
inline bool error_control_allowed(NmtState s) { return s != NmtState::Initialising; }

}  // namespace canopen
