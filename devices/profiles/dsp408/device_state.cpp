#include "devices/profiles/dsp408/device_state.h"

namespace dsp408 {

std::string_view to_string(DeviceState s) {
  switch (s) {
    case DeviceState::NotReady: return "NOT_READY";
    case DeviceState::Init: return "INIT";
    case DeviceState::Disabled: return "DISABLED";
    case DeviceState::Hold: return "HOLD";
    case DeviceState::Active: return "DEVICE_MODE_ACTIVE";
    case DeviceState::FaultReaction: return "FAULT_REACTION";
    case DeviceState::FaultHold: return "FAULT_HOLD";
    case DeviceState::Fault: return "FAULT";
  }
  return "?";
}

}  // namespace dsp408
