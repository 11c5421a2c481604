// devices/vtvpcd/discrete_outputs: the Discrete Outputs word from the table built once per DO
// assignment is bit for bit the word of the rule (DO1 = bit 1, OK = bit 2, DO2..DO7 = bits 3..8,
// shorted outputs 0) for every assignment of functions and every state.
#include "devices/vtvpcd/discrete_outputs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace vtvpcd {
namespace {

bool rule(OutputFunction f, const OutputState& s) {
  const ControlOutputs& c = *s.control;
  switch (f) {
    case OutputFunction::ControllerActive: return c.energised;
    case OutputFunction::AngleWindow: return std::abs(c.alpha_res - s.alpha_meas) <= 5.0;
    case OutputFunction::PressureBranch: return c.branch == Branch::Pressure;
    case OutputFunction::PowerBranch: return c.branch == Branch::Power;
    case OutputFunction::PressureWindow: return std::abs(c.p_r - c.p_ctrl) <= 5.0 * s.p_ref_bar / 100.0;
    case OutputFunction::SlaveMode: return s.slave;
    case OutputFunction::BinarySetInUse: return s.binary;
    case OutputFunction::Off: return false;
  }
  return false;
}

std::uint16_t rule_word(const std::array<OutputFunction, 7>& f, const OutputState& s, std::uint8_t shorted) {
  std::uint16_t w = 0;
  if (rule(f[0], s)) w |= 0x0001;
  if (s.ok) w |= 0x0002;
  for (std::size_t n = 1; n < 7; ++n)
    if (rule(f[n], s)) w |= static_cast<std::uint16_t>(1u << (n + 1));
  return static_cast<std::uint16_t>(w & ~shorted);
}

TEST(VtvpcdDiscreteOutputs, TableWordIsTheRuleForEveryAssignmentAndState) {
  std::uint64_t rng = 42;
  auto next = [&rng] {
    rng = rng * 6364136223846793005ull + 1442695040888963407ull;
    return rng >> 20;
  };
  for (int a = 0; a < 300; ++a) {
    std::array<OutputFunction, 7> functions{};
    for (auto& f : functions) f = static_cast<OutputFunction>(next() % 8);
    if (a == 0) functions = Settings{}.do_functions;
    const DiscreteOutputs outputs(functions);
    for (int i = 0; i < 200; ++i) {
      ControlOutputs c;
      c.energised = next() % 2;
      c.branch = static_cast<Branch>(next() % 5);
      c.alpha_res = static_cast<double>(next() % 200) / 10.0;
      c.p_r = static_cast<double>(next() % 400);
      c.p_ctrl = c.p_r + static_cast<double>(next() % 400) / 10.0 - 20.0;
      if (i == 7) c.p_ctrl = std::nan("");
      OutputState s;
      s.control = &c;
      s.alpha_meas = static_cast<double>(next() % 200) / 10.0;
      s.p_ref_bar = 350.0;
      s.ok = next() % 2;
      s.slave = next() % 2;
      s.binary = next() % 2;
      const auto shorted = static_cast<std::uint8_t>(next() % 4 == 0 ? next() : 0);
      ASSERT_EQ(outputs.word(s, shorted), rule_word(functions, s, shorted)) << a << " " << i;
      for (int f = 0; f < 8; ++f)
        ASSERT_EQ(output_function_value(static_cast<OutputFunction>(f), s), rule(static_cast<OutputFunction>(f), s));
    }
  }
}

}  // namespace
}  // namespace vtvpcd
