#include "devices/profiles/dsp408/device_state_machine.h"

#include "devices/profiles/dsp408/control_word.h"

namespace dsp408 {

namespace {
// More than any chain can take (INIT → DISABLED → HOLD → ACTIVE is three steps, a fault reset
// followed by a chain four); a guard, not a limit the manual knows.
constexpr int kMaxChain = 8;

/// The manual's name of a step (§5.2.2); TR_567 and TR_0 are named by their callers.
std::string_view transition_name(DeviceState from, DeviceState to) {
  using S = DeviceState;
  if (to == S::FaultReaction) return "TR_8";
  if (from == S::FaultReaction) return to == S::FaultHold ? "TR_9" : "TR_12";
  if (from == S::Fault || from == S::FaultHold) return to == S::Hold ? "TR_11" : "TR_10";
  if (from == S::NotReady && to == S::Init) return "TR_1";
  if (from == S::Init && to == S::Disabled) return "TR_2";
  if (from == S::Disabled && to == S::Hold) return "TR_3";
  if (from == S::Hold && to == S::Active) return "TR_4";
  if (from == S::Active && to == S::Hold) return "TR_5";
  if (from == S::Hold && to == S::Disabled) return "TR_6";
  if (from == S::Disabled && to == S::Init) return "TR_7";
  return "";
}

/// Sets the cause of the changes an entry point runs, and puts the previous one back after.
class CauseScope {
 public:
  CauseScope(DeviceStateMachine::Cause& slot, DeviceStateMachine::Cause c) : slot_(slot), saved_(slot) { slot = c; }
  ~CauseScope() { slot_ = saved_; }
  CauseScope(const CauseScope&) = delete;
  CauseScope& operator=(const CauseScope&) = delete;

 private:
  DeviceStateMachine::Cause& slot_;
  DeviceStateMachine::Cause saved_;
};
}  // namespace

void DeviceStateMachine::record(std::string_view from, std::string_view to, std::string_view transition) {
  if (!recorder_) return;
  recorder_(devices::Transition{0, 0, machine_, from, to, transition, cause_.cause, cause_.value, cause_.detail});
}

void DeviceStateMachine::go(DeviceState to, std::string_view transition) {
  const DeviceState from = state_;
  if (from == to) return;
  state_ = to;
  last_ = {from, to, cw_};
  ++transitions_;
  record(to_string(from), to_string(to), transition.empty() ? transition_name(from, to) : transition);
  if (listener_) listener_(from, to);
}

void DeviceStateMachine::power_on(Cause cause) {
  const CauseScope scope(cause_, cause);
  // From OFF it is the manual's TR_0; an application reset (NMT Reset Node) runs the self test
  // again without a name of its own.
  record(off_ ? "OFF" : to_string(state_), to_string(DeviceState::NotReady), off_ ? "TR_0" : "");
  off_ = false;
  cw_ = 0;
  state_ = DeviceState::NotReady;
  go(DeviceState::Init);
}

void DeviceStateMachine::power_off() {
  if (off_) return;
  const CauseScope scope(cause_, {devices::TransitionCause::Power, 0, {}});
  record(to_string(state_), "OFF", "");
  off_ = true;
}

void DeviceStateMachine::write_control_word(std::uint16_t cw, std::string_view via) {
  const bool reset_edge = (cw & control::kResetFault) && !(cw_ & control::kResetFault);
  cw_ = cw;
  const CauseScope scope(cause_, {devices::TransitionCause::ControlWord, cw, via});
  if (!local_) evaluate(reset_edge);
}

void DeviceStateMachine::evaluate(bool reset_edge) {
  const bool d = cw_ & control::kDisable, h = cw_ & control::kHoldEnable, m = cw_ & control::kDeviceModeActive;
  for (int i = 0; i < kMaxChain; ++i) {
    switch (state_) {
      case DeviceState::Init:
        if (d && enable_) {
          go(DeviceState::Disabled);  // TR_2
          continue;
        }
        return;
      case DeviceState::Disabled:
        if (d && h) {
          go(DeviceState::Hold);  // TR_3
          continue;
        }
        if (!d && !h && !m) {
          go(DeviceState::Init);  // TR_7
          continue;
        }
        return;
      case DeviceState::Hold:
        if (d && h && m && active_allowed_) {
          go(DeviceState::Active);  // TR_4
          continue;
        }
        if (!m && !h) {
          go(DeviceState::Disabled);  // TR_6
          continue;
        }
        return;
      case DeviceState::Active:
        if (!m) {
          go(DeviceState::Hold);  // TR_5
          continue;
        }
        return;
      case DeviceState::Fault:
      case DeviceState::FaultHold:
        if (!reset_edge) return;
        reset_edge = false;  // one edge resets once
        if (strict_reset_ && (state_ == DeviceState::Fault) == h) return;  // TR_10 only from FAULT, TR_11 only from FAULT_HOLD
        if (fault_reset_ && !fault_reset_()) return;
        go(h ? DeviceState::Hold : DeviceState::Disabled);  // TR_11 / TR_10
        continue;
      case DeviceState::NotReady:
      case DeviceState::FaultReaction:
        return;
    }
  }
}

bool DeviceStateMachine::error(Cause cause) {
  const CauseScope scope(cause_, cause);
  switch (state_) {
    case DeviceState::Init:
    case DeviceState::Disabled:
    case DeviceState::Hold:
    case DeviceState::Active:
      go(DeviceState::FaultReaction);  // TR_8
      // TR_12: every reaction of these products disables; TR_9 (FAULT_HOLD) only as an option.
      go(fault_hold_ ? DeviceState::FaultHold : DeviceState::Fault);
      return true;
    default: return false;
  }
}

bool DeviceStateMachine::forced_fault(bool from_init, Cause cause) {
  if (state_ == DeviceState::Init && !from_init) return false;
  return error(cause);
}

void DeviceStateMachine::force_init(Cause cause) {
  if (state_ == DeviceState::Disabled || state_ == DeviceState::Hold || state_ == DeviceState::Active) {
    const CauseScope scope(cause_, cause);
    go(DeviceState::Init, "TR_567");
  }
}

void DeviceStateMachine::set_enable_input(bool on) {
  const bool was = enable_;
  enable_ = on;
  if (was == on) return;
  const CauseScope scope(cause_, {devices::TransitionCause::Input, on ? 1u : 0u, "enable input"});
  if (local_) {
    if (on && (state_ == DeviceState::Init || state_ == DeviceState::Disabled)) {
      if (state_ == DeviceState::Init) go(DeviceState::Disabled);
      if (active_allowed_) {
        go(DeviceState::Hold);
        go(DeviceState::Active);
      }
    } else if (!on && (state_ == DeviceState::Active || state_ == DeviceState::Hold)) {
      if (state_ == DeviceState::Active) go(DeviceState::Hold);
      go(DeviceState::Disabled);
    }
    return;
  }
  if (!on) {
    force_init(cause_);
  } else {
    evaluate(false);
  }
}

void DeviceStateMachine::set_active_allowed(bool allowed) { active_allowed_ = allowed; }

}  // namespace dsp408
