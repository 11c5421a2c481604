// What the node hands its CiA 301 services and what they hand back: the node state they read,
// where their frames go, and one small interface per kind of event they raise. The node
// (node.cpp, the composition root, as CANopenNode's CANopen.c) builds every service with only
// the pieces it needs, implements these interfaces and passes each event on (to another service,
// the application, its dispatch table); a service includes no node and knows no sibling, so a
// test builds one with fakes. Plain interfaces, not std::function: events on the per-frame path
// (SYNC, RPDO, TPDO sampling, frames sent) cost one indirect call and never allocate.
#pragma once

#include <cstdint>
#include <string_view>

#include "devices/canopen/nmt_state.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

/// Node-ID of a node without one (LSS only until configured, CiA 305).
inline constexpr std::uint8_t kUnconfiguredNodeId = 0xFF;

/// The node's state the services read. Owned by the node and read by reference: a read costs
/// what a member read costs, and every service sees a change at once.
struct NodeStatus {
  std::uint8_t node_id = 0;
  /// The node-ID the next communication reset applies (LSS, 0x2000-style objects).
  std::uint8_t pending_node_id = 0;
  NmtState nmt_state = NmtState::Initialising;
  sim::Time now{};
  /// No frame in or out before this (e.g. while "saving to EEPROM").
  sim::Time silent_until{};
  bool silent() const { return now < silent_until; }
};

/// Where a service's frames go (the node drops them while off, silent or bus-off).
class FrameSender {
 public:
  virtual void send(const sim::CanFrame& frame) = 0;

 protected:
  ~FrameSender() = default;
};

/// The COB-IDs a service listens on changed (0x1005, a PDO's COB-ID, 0x1016): re-route.
class RoutesChanged {
 public:
  virtual void rebuild_dispatch() = 0;

 protected:
  ~RoutesChanged() = default;
};

/// Emergency to send (SYNC length, RPDO length and deadline): a communication error condition
/// rose or fell; the node raises / clears the EMCY with its communication error register bits.
class EmcyRequests {
 public:
  virtual void raise_emcy(std::uint16_t code) = 0;
  virtual void clear_emcy(std::uint16_t code) = 0;

 protected:
  ~EmcyRequests() = default;
};

/// NMT slave: a node-control command addressed to this node arrived.
class NmtCommandHandler {
 public:
  /// `sender` names who sent it in the transition log.
  virtual void execute_nmt(NmtCommand command, std::string_view sender) = 0;

 protected:
  ~NmtCommandHandler() = default;
};

/// SYNC consumer: a SYNC was accepted. `pdo_counter` is what the TPDOs' start values compare
/// (0 without 0x1019), `counter` what the device sees (the counter byte, if any).
class SyncEvents {
 public:
  virtual void sync_received(std::uint8_t pdo_counter, std::uint8_t counter, sim::Time now) = 0;

 protected:
  ~SyncEvents() = default;
};

/// PDO service: the application's part of a PDO.
class PdoEvents {
 public:
  /// RPDO n (1-based) was received and its mapped objects written.
  virtual void rpdo_received(int number) = 0;
  /// TPDO n is about to be sampled: the device refreshes its mapped values.
  virtual void before_tpdo(int number) = 0;

 protected:
  ~PdoEvents() = default;
};

/// Error control (life guarding) and heartbeat consumer: a watchdog timed out / recovered.
class CommErrorEvents {
 public:
  /// `evidence`: the heartbeat producer's node-ID, the guarding life time in ms.
  virtual void communication_error(CommError error, std::uint32_t evidence) = 0;
  virtual void communication_recovered(CommError error) = 0;

 protected:
  ~CommErrorEvents() = default;
};

/// Store/restore and LSS: the node goes silent (no frame in or out) until `until`.
class SilenceRequest {
 public:
  virtual void go_silent_until(sim::Time until) = 0;

 protected:
  ~SilenceRequest() = default;
};

/// LSS slave: node-ID configuration.
class LssEvents {
 public:
  /// The node-ID the next communication reset applies changed.
  virtual void set_pending_node_id(std::uint8_t id) = 0;
  /// CiA 305 transition 4: an unconfigured node got its node-ID; reset communication to use it.
  virtual void apply_pending_node_id() = 0;

 protected:
  ~LssEvents() = default;
};

}  // namespace canopen
