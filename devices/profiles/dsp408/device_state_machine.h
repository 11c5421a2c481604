// The CiA DSP 408 device state machine as the MD2/DSV manuals (§5.2.2) describe it: states
// NOT_READY → INIT → DISABLED → HOLD → DEVICE_MODE_ACTIVE and the fault states, driven by the
// control word (bus operation) or by the local enable input (local operation).
//
// Transitions are level-triggered on control-word bits D, H, M and re-evaluated until none
// fires, so one write of 0x0007 in INIT runs TR_2, TR_3, TR_4. The reset-fault bit R acts on
// its 0→1 edge only (TR_10 / TR_11), and only when the product says no error is still present.
// A control word that matches no transition leaves the state alone (0x0005 in ACTIVE stays
// ACTIVE).
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

#include "devices/profiles/dsp408/device_state.h"
#include "devices/transition_log.h"

namespace dsp408 {

/// Why the machine moves: the entry point's own (control word, enable input) or the caller's
/// (an NMT command, a guarding timeout, a device fault with its EMCY code, power).
struct StateCause {
  devices::TransitionCause cause = devices::TransitionCause::Internal;
  std::uint32_t value = 0;
  std::string_view detail;
};

class DeviceStateMachine {
 public:
  /// Called on every state change (after the state changed), including each step of a chain.
  using Listener = std::function<void(DeviceState from, DeviceState to)>;
  /// Asked when R rises in a fault state: true if no error is present any more (the product
  /// then clears its error bookkeeping); false keeps the fault.
  using FaultReset = std::function<bool()>;

  using Cause = StateCause;
  /// Receives every state change as a log entry (machine, TR_n, cause; t_us left 0 for the
  /// product to stamp): the product puts it into its Device's transition log.
  using Recorder = std::function<void(const devices::Transition&)>;

  void set_listener(Listener l) { listener_ = std::move(l); }
  /// `machine`: static text ("dsp408", "dsp408.ch2").
  void set_recorder(std::string_view machine, Recorder r) {
    machine_ = machine;
    recorder_ = std::move(r);
  }
  void set_fault_reset(FaultReset f) { fault_reset_ = std::move(f); }

  /// TR_0 + TR_1: power-on / application reset; control word 0, INIT.
  void power_on(Cause cause = {devices::TransitionCause::Boot, 0, {}});
  /// The supply is off: recorded as OFF (the state stays for the listener; off() says it).
  void power_off();
  bool off() const { return off_; }

  /// A control word from the bus (SDO or RPDO): stores it, detects the R edge, evaluates.
  /// `via` names the service in the log ("SDO", "RPDO").
  void write_control_word(std::uint16_t cw, std::string_view via = {});
  std::uint16_t control_word() const { return cw_; }

  /// TR_8 → FAULT_REACTION → TR_12 → FAULT (TR_9 → FAULT_HOLD with set_fault_hold) from INIT, DISABLED, HOLD or ACTIVE (an error).
  /// Returns true if the state changed.
  bool error(Cause cause = {devices::TransitionCause::DeviceFault, 0, {}});
  /// TR_8 forced by the communication state machine (NMT Stop, Reset Communication, life
  /// guarding): from DISABLED, HOLD, ACTIVE, and from INIT only if `from_init`.
  bool forced_fault(bool from_init, Cause cause = {});
  /// TR_567: back to INIT from DISABLED, HOLD or ACTIVE (NMT Reset Node, the enable input).
  void force_init(Cause cause = {});

  /// The hardware enable input. Bus operation: while 0, TR_2 is blocked; a 1→0 edge forces
  /// TR_567; back at 1 the stored control word is evaluated again. Local operation: a 0→1 edge
  /// enables (INIT/DISABLED → ACTIVE), a 1→0 edge disables (ACTIVE → DISABLED).
  void set_enable_input(bool on);
  bool enable_input() const { return enable_; }

  /// Bus operation (control word from CAN) or local operation (enable input).
  void set_local(bool local) { local_ = local; }
  bool local() const { return local_; }

  /// TR_4 is possible only with a control mode selected (MD2/DSV: mode 0 has no function).
  void set_active_allowed(bool allowed);

  /// Options (both off by default): the fault reaction ends in FAULT_HOLD (TR_9) instead of
  /// FAULT (TR_12); the fault reset takes the strict CiA sources only (TR_10 from FAULT with
  /// H = 0, TR_11 from FAULT_HOLD with H = 1; any other R edge does nothing).
  void set_fault_hold(bool on) { fault_hold_ = on; }
  void set_strict_reset_sources(bool on) { strict_reset_ = on; }

  DeviceState state() const { return state_; }

  /// The last state change and the control word then (for watchers: the live control plane).
  struct Transition {
    DeviceState from = DeviceState::NotReady;
    DeviceState to = DeviceState::NotReady;
    std::uint16_t control_word = 0;
  };
  const Transition& last_transition() const { return last_; }
  std::uint32_t transitions() const { return transitions_; }

 private:
  void go(DeviceState to, std::string_view transition = {});
  void record(std::string_view from, std::string_view to, std::string_view transition);
  void evaluate(bool reset_edge);

  DeviceState state_ = DeviceState::NotReady;
  std::uint16_t cw_ = 0;
  bool enable_ = true;
  bool local_ = false;
  bool active_allowed_ = true;
  bool fault_hold_ = false;
  bool strict_reset_ = false;
  bool off_ = true;  ///< before the first power-on, and after power_off()
  Cause cause_;     ///< of the change running now
  std::string_view machine_ = "dsp408";
  Listener listener_;
  Recorder recorder_;
  FaultReset fault_reset_;
  Transition last_;
  std::uint32_t transitions_ = 0;
};

}  // namespace dsp408
