// Control word 0x6040 (and its channel copies) and status word 0x6041: bit assignments of
// CiA DSP 408 as the MD2 and DSV manuals print them.
#pragma once

#include <cstdint>

#include "devices/profiles/dsp408/device_state.h"

namespace dsp408 {

namespace control {
constexpr std::uint16_t kDisable = 1u << 0;           ///< D
constexpr std::uint16_t kHoldEnable = 1u << 1;        ///< H
constexpr std::uint16_t kDeviceModeActive = 1u << 2;  ///< M
constexpr std::uint16_t kResetFault = 1u << 3;        ///< R: a 0→1 edge resets a fault
constexpr std::uint16_t kReleaseSolenoidA = 1u << 13; ///< DSV, mode of operation 3 only
constexpr std::uint16_t kReleaseSolenoidB = 1u << 14;
}  // namespace control

namespace status {
constexpr std::uint16_t kLocal = 1u << 4;
constexpr std::uint16_t kWarning = 1u << 5;
constexpr std::uint16_t kRampRunning = 1u << 9;
constexpr std::uint16_t kWindowReached = 1u << 12;
constexpr std::uint16_t kSolenoidAReleased = 1u << 13;
constexpr std::uint16_t kSolenoidBReleased = 1u << 14;
}  // namespace status

/// The flags a product adds to the state bits.
struct StatusFlags {
  bool local = false;
  bool warning = false;
  bool ramp_running = false;
  bool window_reached = false;
  bool solenoid_a_released = false;
  bool solenoid_b_released = false;
};

constexpr std::uint16_t status_word(DeviceState s, const StatusFlags& f) {
  std::uint16_t w = state_bits(s);
  if (f.local) w |= status::kLocal;
  if (f.warning) w |= status::kWarning;
  if (f.ramp_running) w |= status::kRampRunning;
  if (f.window_reached) w |= status::kWindowReached;
  if (f.solenoid_a_released) w |= status::kSolenoidAReleased;
  if (f.solenoid_b_released) w |= status::kSolenoidBReleased;
  return w;
}

}  // namespace dsp408
