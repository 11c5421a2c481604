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

/// The value of every output function at once: bit f = the value of OutputFunction f.
std::uint8_t function_values(const OutputState& s);
bool output_function_value(OutputFunction f, const OutputState& s);

/// The functions of DO1, DO2..DO7 resolved once (settings do not change at run time): the word
/// of a cycle is one look-up on the values of the eight functions.
class DiscreteOutputs {
 public:
  explicit DiscreteOutputs(const std::array<OutputFunction, 7>& functions);
  std::uint16_t word(const OutputState& s, std::uint8_t shorted) const {
    const std::uint16_t w = by_values_[function_values(s)] | (s.ok ? dout::kOk : 0);
    return static_cast<std::uint16_t>(w & ~shorted);
  }

 private:
  std::array<std::uint16_t, 256> by_values_{};  ///< DO1, DO2..DO7 bits by function values
};

}  // namespace vtvpcd
