#include "devices/vtvpcd/command_sources.h"

#include <algorithm>

#include "devices/vtvpcd/parameter_conversion.h"

namespace vtvpcd {

namespace {
constexpr double kMaxPressureBar = 600.0;
constexpr double kMaxRampS = 300.0;
constexpr double kMinTiMs = 2.0, kMaxTiMs = 30000.0;
constexpr double kMaxKp = 255.0;
}  // namespace

PumpLimits limits_of(PumpType type) {
  return type == PumpType::A4VSG ? PumpLimits{-100.0, 100.0} : PumpLimits{0.0, 100.0};
}

SelectedCommands select_commands(const SetSelection& sel, const CardParameters& p, const AnalogInputs& analog,
                                 const Settings& s) {
  SelectedCommands c;
  const int k = sel.set;
  const int g = sel.group();
  if (sel.binary) {
    c.alpha_pct = to_eu(p.angle_cmd_binary(k), kScalePercent);
    c.pressure_bar = to_eu(p.press_cmd_binary(k), kScaleTable);
    c.power_pct = to_eu(p.power_cmd_binary(k), kScaleTable);
    c.ramp_alpha_s = to_eu(p.angle_ramp_binary(k), kScaleRamp);
    c.ramp_pressure_s = to_eu(p.press_ramp_binary(k), kScaleRamp);
  } else {
    if (s.cmd_source == CommandSource::Bus) {
      c.alpha_pct = to_eu(p.angle_cmd_bus(), kScalePercent);
      const double pressure = to_eu(p.pressure_cmd_bus(), kScalePercent);
      c.pressure_bar = s.pressure_bus_unit == PressureBusUnit::Bar ? pressure : pressure * s.p_ref_bar / 100.0;
      c.power_pct = to_eu(p.power_cmd_bus(), kScalePercent);
    } else {
      c.alpha_pct = analog.angle_b14_b16_pct;
      c.pressure_bar = analog.pressure_b18_b20_bar;
      c.power_pct = analog.power_f8_f10_pct;
    }
    if (s.direct_mode_ramps_set0) {
      c.ramp_alpha_s = to_eu(p.angle_ramp_binary(0), kScaleRamp);
      c.ramp_pressure_s = to_eu(p.press_ramp_binary(0), kScaleRamp);
    }
  }
  c.kp = to_eu(p.contr_p(g), kScaleGain);
  c.ti_ms = to_eu(p.contr_i(g), kScaleOne);
  c.slave_alpha_pct = s.cmd_source == CommandSource::Bus ? to_eu(p.res_angle_cmd_bus(), kScalePercent)
                                                         : analog.angle_b2_b4_pct;

  const auto lim = limits_of(s.pump_type);
  c.alpha_pct = std::clamp(c.alpha_pct, lim.alpha_lo, lim.alpha_hi);
  c.slave_alpha_pct = std::clamp(c.slave_alpha_pct, lim.alpha_lo, lim.alpha_hi);
  c.pressure_bar = std::clamp(c.pressure_bar, 0.0, kMaxPressureBar);
  c.power_pct = std::clamp(c.power_pct, 0.0, 100.0);
  c.ramp_alpha_s = std::clamp(c.ramp_alpha_s, 0.0, kMaxRampS);
  c.ramp_pressure_s = std::clamp(c.ramp_pressure_s, 0.0, kMaxRampS);
  c.kp = std::clamp(c.kp, 0.0, kMaxKp);
  c.ti_ms = std::clamp(c.ti_ms, kMinTiMs, kMaxTiMs);
  return c;
}

}  // namespace vtvpcd
