#include "devices/profiles/dsp408/device_state_machine.h"

#include "devices/profiles/dsp408/control_word.h"

namespace dsp408 {

namespace {
// More than any chain can take (INIT → DISABLED → HOLD → ACTIVE is three steps, a fault reset
// followed by a chain four); a guard, not a limit the manual knows.
constexpr int kMaxChain = 8;
}  // namespace

void DeviceStateMachine::go(DeviceState to) {
  const DeviceState from = state_;
  if (from == to) return;
  state_ = to;
  last_ = {from, to, cw_};
  ++transitions_;
  if (listener_) listener_(from, to);
}

void DeviceStateMachine::power_on() {
  cw_ = 0;
  state_ = DeviceState::NotReady;
  go(DeviceState::Init);
}

void DeviceStateMachine::write_control_word(std::uint16_t cw) {
  const bool reset_edge = (cw & control::kResetFault) && !(cw_ & control::kResetFault);
  cw_ = cw;
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

bool DeviceStateMachine::error() {
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

bool DeviceStateMachine::forced_fault(bool from_init) {
  if (state_ == DeviceState::Init && !from_init) return false;
  return error();
}

void DeviceStateMachine::force_init() {
  if (state_ == DeviceState::Disabled || state_ == DeviceState::Hold || state_ == DeviceState::Active) {
    go(DeviceState::Init);  // TR_567
  }
}

void DeviceStateMachine::set_enable_input(bool on) {
  const bool was = enable_;
  enable_ = on;
  if (was == on) return;
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
    force_init();
  } else {
    evaluate(false);
  }
}

void DeviceStateMachine::set_active_allowed(bool allowed) { active_allowed_ = allowed; }

}  // namespace dsp408
