// Discrete Outputs 0x2F26 (manual §4.52: bit 1 = DO1, bit 2 = OK, bits 3..8 = DO2..DO7). The
// manual names the outputs but not their functions (set in BODAC); this emulator gives DO1..DO7
// the configurable functions of settings.h (digest §3.5, A27). OK = no error active. An output
// whose driver is shorted (faults 26..33) reads 0.
#pragma once

#include <array>
#include <cstdint>

#include "devices/vtvpcd/pump_controller.h"
#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

namespace dout {
inline constexpr std::uint16_t kDo1 = 0x0001;
inline constexpr std::uint16_t kOk = 0x0002;
}  // namespace dout

struct OutputState {
  const ControlOutputs* control = nullptr;
  double alpha_meas = 0;
  double p_ref_bar = 350;
  bool ok = true;
  bool slave = false;
  bool binary = false;
};

bool output_function_value(OutputFunction f, const OutputState& s);
std::uint16_t discrete_outputs(const std::array<OutputFunction, 7>& functions, const OutputState& s,
                               std::uint8_t shorted);

}  // namespace vtvpcd
