// The device side of a node: what a product (valve, pump controller, encoder) implements to
// react to protocol events. Every method has a do-nothing default, so a generic EDS node needs
// none of them.
#pragma once

#include <cstdint>

#include "devices/canopen/nmt_state.h"
#include "sim/time.h"

namespace canopen {

class Application {
 public:
  virtual ~Application() = default;

  /// Power-on or NMT Reset Node: the 0x2000-0x9FFF area has been reloaded (stored values or
  /// defaults); put the device model back to its power-on state.
  virtual void on_reset_application() {}
  /// The node loses power (before it goes silent): state machines show OFF until power-on.
  virtual void on_power_off() {}
  /// A communication reset starts (power-on, Reset Node, Reset Communication); the device may set
  /// the node-ID to use (Node::set_pending_node_id) before the 0x1000-0x1FFF area is reloaded.
  virtual void on_reset_communication() {}
  /// The communication reset is done (COB-IDs recomputed); e.g. regenerate PDO mappings.
  virtual void after_reset_communication() {}
  /// An NMT command addressed to this node arrived; called before the stack acts on it.
  virtual void on_nmt_command(NmtCommand) {}
  virtual void on_nmt_state_changed(NmtState /*from*/, NmtState /*to*/) {}
  /// SYNC consumed (in Operational/Pre-operational); counter is 0 without a counter byte.
  virtual void on_sync(std::uint8_t /*counter*/) {}
  /// RPDO n (1-based) was received and its mapped objects written (Operational only).
  virtual void on_rpdo(int /*pdo_number*/) {}
  /// A TPDO is about to be sampled: refresh the mapped process values.
  virtual void before_tpdo(int /*pdo_number*/) {}
  /// Life guarding or heartbeat consumer timeout. Return true if the device fully handled it;
  /// otherwise the stack sends its EMCY and applies 0x1029:01 (if present).
  virtual bool on_communication_error(CommError) { return false; }
  /// The communication error condition ended (guarding resumed, heartbeat back).
  virtual void on_communication_recovered(CommError) {}
  /// The CAN controller became error passive (true) or error active again (false). Return true
  /// if the device handled it; otherwise the stack raises / clears ErrorControlPolicy's
  /// error_passive_emcy.
  virtual bool on_error_passive(bool /*passive*/) { return false; }
  /// Device logic once per tick, after the tick's frames and before TPDO evaluation.
  virtual void process(sim::Time /*now*/, sim::Duration /*dt*/) {}
};

}  // namespace canopen
