#include "devices/vtvpcd/discrete_outputs.h"

#include <cmath>

namespace vtvpcd {

namespace {
constexpr double kAngleWindowPct = 5.0;
constexpr double kPressureWindowPct = 5.0;  // of p_ref

constexpr unsigned bit(OutputFunction f) { return 1u << static_cast<unsigned>(f); }
}  // namespace

std::uint8_t function_values(const OutputState& s) {
  const ControlOutputs& c = *s.control;
  unsigned v = 0;
  if (c.energised) v |= bit(OutputFunction::ControllerActive);
  if (std::abs(c.alpha_res - s.alpha_meas) <= kAngleWindowPct) v |= bit(OutputFunction::AngleWindow);
  if (c.branch == Branch::Pressure) v |= bit(OutputFunction::PressureBranch);
  if (c.branch == Branch::Power) v |= bit(OutputFunction::PowerBranch);
  if (std::abs(c.p_r - c.p_ctrl) <= kPressureWindowPct * s.p_ref_bar / 100.0) v |= bit(OutputFunction::PressureWindow);
  if (s.slave) v |= bit(OutputFunction::SlaveMode);
  if (s.binary) v |= bit(OutputFunction::BinarySetInUse);
  return static_cast<std::uint8_t>(v);  // OutputFunction::Off: always 0
}

bool output_function_value(OutputFunction f, const OutputState& s) { return (function_values(s) & bit(f)) != 0; }

DiscreteOutputs::DiscreteOutputs(const std::array<OutputFunction, 7>& functions) {
  for (unsigned values = 0; values < by_values_.size(); ++values) {
    std::uint16_t w = 0;
    if (values & bit(functions[0])) w |= dout::kDo1;
    for (std::size_t n = 1; n < functions.size(); ++n) {
      if (values & bit(functions[n])) w |= static_cast<std::uint16_t>(1u << (n + 1));  // DO2 = bit 3 (0x04)
    }
    by_values_[values] = w;
  }
}

}  // namespace vtvpcd
