#include "devices/vtvpcd/discrete_outputs.h"

#include <cmath>

namespace vtvpcd {

namespace {
constexpr double kAngleWindowPct = 5.0;
constexpr double kPressureWindowPct = 5.0;  // of p_ref
}  // namespace

bool output_function_value(OutputFunction f, const OutputState& s) {
  const ControlOutputs& c = *s.control;
  switch (f) {
    case OutputFunction::ControllerActive: return c.energised;
    case OutputFunction::AngleWindow: return std::abs(c.alpha_res - s.alpha_meas) <= kAngleWindowPct;
    case OutputFunction::PressureBranch: return c.branch == Branch::Pressure;
    case OutputFunction::PowerBranch: return c.branch == Branch::Power;
    case OutputFunction::PressureWindow: return std::abs(c.p_r - c.p_ctrl) <= kPressureWindowPct * s.p_ref_bar / 100.0;
    case OutputFunction::SlaveMode: return s.slave;
    case OutputFunction::BinarySetInUse: return s.binary;
    case OutputFunction::Off: return false;
  }
  return false;
}

std::uint16_t discrete_outputs(const std::array<OutputFunction, 7>& functions, const OutputState& s,
                               std::uint8_t shorted) {
  std::uint16_t word = 0;
  if (output_function_value(functions[0], s)) word |= dout::kDo1;
  if (s.ok) word |= dout::kOk;
  for (std::size_t n = 1; n < functions.size(); ++n) {
    if (output_function_value(functions[n], s)) word |= static_cast<std::uint16_t>(1u << (n + 1));  // DO2 = bit 3 (0x04)
  }
  return static_cast<std::uint16_t>(word & ~shorted);
}

}  // namespace vtvpcd
