// devices/vtvpcd/command_sources: the commands of a cycle, gathered from the selected set's raw
// values and converted, are those of the manual's rules as the card first implemented them (the
// reference below reads each object by index), for every command source and set; the
// CommandSelector, which converts only when a raw value changed, gives the same commands as a fresh
// selection in every cycle, including the cycle right after a value was rewritten.
#include "devices/vtvpcd/command_sources.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "devices/vtvpcd/dictionary.h"
#include "devices/vtvpcd/manufacturer_objects.h"
#include "devices/vtvpcd/parameter_conversion.h"

namespace vtvpcd {
namespace {

/// The selection rules read object by object (digest §4.2), independent of CardParameters.
SelectedCommands reference(const SetSelection& sel, const canopen::ObjectDictionary& od, const AnalogInputs& analog,
                           const Settings& s) {
  auto eu = [&od](std::uint16_t index, Scale scale) { return to_eu(od.entry(index, 0)->as<std::int64_t>(), scale); };
  auto at = [](std::uint16_t base, int k) { return static_cast<std::uint16_t>(base + k); };
  SelectedCommands c;
  const int k = sel.set, g = sel.group();
  if (sel.binary) {
    c.alpha_pct = eu(at(idx::kAngleCmdBinary0, k), kScalePercent);
    c.pressure_bar = eu(at(idx::kPressCmdBinary0, k), kScaleTable);
    c.power_pct = eu(at(idx::kPowerCmdBinary0, k), kScaleTable);
    c.ramp_alpha_s = eu(at(idx::kAngleRampBinary0, k), kScaleRamp);
    c.ramp_pressure_s = eu(at(idx::kPressRampBinary0, k), kScaleRamp);
  } else {
    if (s.cmd_source == CommandSource::Bus) {
      c.alpha_pct = eu(idx::kAngleCmdBus, kScalePercent);
      const double pressure = eu(idx::kPressureCmdBus, kScalePercent);
      c.pressure_bar = s.pressure_bus_unit == PressureBusUnit::Bar ? pressure : pressure * s.p_ref_bar / 100.0;
      c.power_pct = eu(idx::kPowerCmdBus, kScalePercent);
    } else {
      c.alpha_pct = analog.angle_b14_b16_pct;
      c.pressure_bar = analog.pressure_b18_b20_bar;
      c.power_pct = analog.power_f8_f10_pct;
    }
    if (s.direct_mode_ramps_set0) {
      c.ramp_alpha_s = eu(idx::kAngleRampBinary0, kScaleRamp);
      c.ramp_pressure_s = eu(idx::kPressRampBinary0, kScaleRamp);
    }
  }
  c.kp = eu(at(idx::kContrPBinary0, 4 * g), kScaleGain);
  c.ti_ms = eu(at(idx::kContrIBinary0, 4 * g), kScaleOne);
  c.slave_alpha_pct = s.cmd_source == CommandSource::Bus ? eu(idx::kResAngleCmdBus, kScalePercent) : analog.angle_b2_b4_pct;
  const auto lim = limits_of(s.pump_type);
  c.alpha_pct = std::clamp(c.alpha_pct, lim.alpha_lo, lim.alpha_hi);
  c.slave_alpha_pct = std::clamp(c.slave_alpha_pct, lim.alpha_lo, lim.alpha_hi);
  c.pressure_bar = std::clamp(c.pressure_bar, 0.0, 600.0);
  c.power_pct = std::clamp(c.power_pct, 0.0, 100.0);
  c.ramp_alpha_s = std::clamp(c.ramp_alpha_s, 0.0, 300.0);
  c.ramp_pressure_s = std::clamp(c.ramp_pressure_s, 0.0, 300.0);
  c.kp = std::clamp(c.kp, 0.0, 255.0);
  c.ti_ms = std::clamp(c.ti_ms, 2.0, 30000.0);
  return c;
}

void expect_same(const SelectedCommands& a, const SelectedCommands& b, const std::string& where) {
  EXPECT_EQ(a.alpha_pct, b.alpha_pct) << where;
  EXPECT_EQ(a.pressure_bar, b.pressure_bar) << where;
  EXPECT_EQ(a.power_pct, b.power_pct) << where;
  EXPECT_EQ(a.ramp_alpha_s, b.ramp_alpha_s) << where;
  EXPECT_EQ(a.ramp_pressure_s, b.ramp_pressure_s) << where;
  EXPECT_EQ(a.kp, b.kp) << where;
  EXPECT_EQ(a.ti_ms, b.ti_ms) << where;
  EXPECT_EQ(a.slave_alpha_pct, b.slave_alpha_pct) << where;
}

struct Lcg {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  std::uint64_t next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 17;
  }
};

TEST(VtvpcdCommandSources, SelectorMatchesTheRulesInEveryCycleWhateverChanges) {
  struct Mode {
    CommandSource source;
    bool ramps_set0;
    PressureBusUnit unit;
    PumpType pump;
  };
  const Mode modes[] = {{CommandSource::Bus, false, PressureBusUnit::Bar, PumpType::A4VSO},
                        {CommandSource::Bus, true, PressureBusUnit::PercentOfReference, PumpType::A4VSG},
                        {CommandSource::Analog, false, PressureBusUnit::Bar, PumpType::A2V},
                        {CommandSource::Analog, true, PressureBusUnit::Bar, PumpType::A4VSG}};
  for (const Mode& m : modes) {
    Settings s;
    s.cmd_source = m.source;
    s.direct_mode_ramps_set0 = m.ramps_set0;
    s.pressure_bus_unit = m.unit;
    s.pump_type = m.pump;
    canopen::ObjectDictionary od = build_dictionary(s);
    const CardParameters params(od);
    CommandSelector selector;
    Lcg rng;
    std::vector<const ObjectSpec*> writable;
    for (const auto& spec : manufacturer_objects())
      if (!spec.read_only) writable.push_back(&spec);
    AnalogInputs analog{10.0, -20.0, 150.0, 40.0};
    for (int cycle = 0; cycle < 4000; ++cycle) {
      // Most cycles change nothing; some rewrite one object (sometimes with its present value),
      // move an analog input or switch the set.
      const auto r = rng.next() % 8;
      if (r == 0) {
        const ObjectSpec& spec = *writable[rng.next() % writable.size()];
        auto* e = od.entry(spec.index, 0);
        const std::uint64_t v = rng.next() % 3 == 0 ? canopen::decode_unsigned(e->value) : rng.next();
        canopen::encode_unsigned(v, e->value);  // any raw value: out-of-range ones are clamped in use
      } else if (r == 1) {
        analog.angle_b14_b16_pct = static_cast<double>(rng.next() % 2400) / 10.0 - 120.0;
        analog.angle_b2_b4_pct = static_cast<double>(rng.next() % 2400) / 10.0 - 120.0;
        analog.pressure_b18_b20_bar = static_cast<double>(rng.next() % 7000) / 10.0 - 50.0;
        analog.power_f8_f10_pct = static_cast<double>(rng.next() % 1200) / 10.0 - 10.0;
      }
      SetSelection sel;
      sel.set = static_cast<int>((cycle / 97) % 16);
      sel.binary = (cycle / 53) % 3 == 0;
      const std::string where = "mode " + std::to_string(static_cast<int>(m.source)) + " cycle " + std::to_string(cycle);
      const SelectedCommands want = reference(sel, od, analog, s);
      expect_same(select_commands(sel, params, analog, s), want, where);
      expect_same(selector.select(sel, params, analog, s), want, where);
      if (testing::Test::HasFailure()) return;
    }
  }
}

TEST(VtvpcdCommandSources, ARewrittenValueIsUsedInTheNextSelection) {
  Settings s;
  canopen::ObjectDictionary od = build_dictionary(s);
  const CardParameters params(od);
  CommandSelector selector;
  SetSelection sel;  // direct mode, bus commands
  const AnalogInputs analog;
  od.set<std::int32_t>(idx::kAngleCmdBus, 0, 13107);
  EXPECT_EQ(selector.select(sel, params, analog, s).alpha_pct, to_eu(13107, kScalePercent));
  EXPECT_EQ(selector.select(sel, params, analog, s).alpha_pct, to_eu(13107, kScalePercent));
  od.set<std::int32_t>(idx::kAngleCmdBus, 0, 13108);  // one LSB more: a new value at once
  EXPECT_EQ(selector.select(sel, params, analog, s).alpha_pct, to_eu(13108, kScalePercent));
  od.set<std::uint16_t>(idx::kContrPBinary0, 0, 384);  // group 0: Kp 3.0
  EXPECT_EQ(selector.select(sel, params, analog, s).kp, 3.0);
  od.entry(idx::kContrPBinary0, 0)->reset_to_default(s.node_id);  // as a reset does: 128
  EXPECT_EQ(selector.select(sel, params, analog, s).kp, 1.0);
  sel.binary = true;  // a set switch with equal raw values elsewhere still selects the set's values
  sel.set = 3;
  od.set<std::int32_t>(static_cast<std::uint16_t>(idx::kAngleCmdBinary0 + 3), 0, 13108);
  EXPECT_EQ(selector.select(sel, params, analog, s).alpha_pct, to_eu(13108, kScalePercent));
  EXPECT_NEAR(selector.select(sel, params, analog, s).pressure_bar, 350.0, 0.01);  // start-up table value
}

}  // namespace
}  // namespace vtvpcd
