// CiA DSP 408 device states and their coding in status word bits 3..0 (R M H D).
// The MD2/DSV manuals lost the state diagram that carried the codes; these are the CiA 408 ones.
#pragma once

#include <cstdint>
#include <string_view>

namespace dsp408 {

enum class DeviceState : std::uint8_t {
  NotReady,       ///< self test, not visible on the bus
  Init,           ///< parameters loaded, functions disabled
  Disabled,       ///< functions disabled, modes may be changed
  Hold,           ///< last set point held
  Active,         ///< DEVICE_MODE_ACTIVE: the control mode follows the set point
  FaultReaction,  ///< transient: the error reaction runs
  FaultHold,      ///< fault with the hold set point active
  Fault,          ///< fault with functions disabled
};

/// Status word bits 3..0 (Ready, Device mode active, Hold, Disabled) of a state.
constexpr std::uint16_t state_bits(DeviceState s) {
  switch (s) {
    case DeviceState::NotReady: return 0x0;
    case DeviceState::Init: return 0x8;
    case DeviceState::Disabled: return 0x9;
    case DeviceState::Hold: return 0xB;
    case DeviceState::Active: return 0xF;
    case DeviceState::FaultReaction: return 0x7;
    case DeviceState::FaultHold: return 0x3;
    case DeviceState::Fault: return 0x1;
  }
  return 0;
}

constexpr bool is_fault(DeviceState s) {
  return s == DeviceState::FaultReaction || s == DeviceState::FaultHold || s == DeviceState::Fault;
}

std::string_view to_string(DeviceState s);

}  // namespace dsp408
