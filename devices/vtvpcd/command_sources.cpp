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

// Inlined into CommandSelector::select(): it runs in every cycle.
[[gnu::always_inline]] inline CommandInputs gather_commands(const SetSelection& sel, const CardParameters& p,
                                                            const AnalogInputs& analog, const Settings& s) {
  using Source = CommandInputs::Source;
  CommandInputs in;
  const int k = sel.set;
  if (sel.binary) {
    in.source = Source::Binary;
    in.alpha = p.angle_cmd_binary(k);
    in.pressure = p.press_cmd_binary(k);
    in.power = p.power_cmd_binary(k);
    in.ramp_alpha = p.angle_ramp_binary(k);
    in.ramp_pressure = p.press_ramp_binary(k);
  } else {
    if (s.cmd_source == CommandSource::Bus) {
      in.source = Source::Bus;
      in.alpha = p.angle_cmd_bus();
      in.pressure = p.pressure_cmd_bus();
      in.power = p.power_cmd_bus();
    } else {
      in.source = Source::Analog;
      in.analog_alpha = analog.angle_b14_b16_pct;
      in.analog_pressure = analog.pressure_b18_b20_bar;
      in.analog_power = analog.power_f8_f10_pct;
    }
    if (s.direct_mode_ramps_set0) {
      in.ramp_alpha = p.angle_ramp_binary(0);
      in.ramp_pressure = p.press_ramp_binary(0);
    }
  }
  in.contr_p = p.contr_p(sel.group());
  in.contr_i = p.contr_i(sel.group());
  if (s.cmd_source == CommandSource::Bus) {
    in.slave_alpha = p.res_angle_cmd_bus();
  } else {
    in.analog_slave = analog.angle_b2_b4_pct;
  }
  return in;
}

SelectedCommands convert_commands(const CommandInputs& in, const Settings& s) {
  using Source = CommandInputs::Source;
  SelectedCommands c;
  switch (in.source) {
    case Source::Binary:
      c.alpha_pct = to_eu(in.alpha, kScalePercent);
      c.pressure_bar = to_eu(in.pressure, kScaleTable);
      c.power_pct = to_eu(in.power, kScaleTable);
      break;
    case Source::Bus: {
      c.alpha_pct = to_eu(in.alpha, kScalePercent);
      const double pressure = to_eu(in.pressure, kScalePercent);
      c.pressure_bar = s.pressure_bus_unit == PressureBusUnit::Bar ? pressure : pressure * s.p_ref_bar / 100.0;
      c.power_pct = to_eu(in.power, kScalePercent);
      break;
    }
    case Source::Analog:
      c.alpha_pct = in.analog_alpha;
      c.pressure_bar = in.analog_pressure;
      c.power_pct = in.analog_power;
      break;
  }
  c.ramp_alpha_s = to_eu(in.ramp_alpha, kScaleRamp);  // 0 (no ramp) where none applies
  c.ramp_pressure_s = to_eu(in.ramp_pressure, kScaleRamp);
  c.kp = to_eu(in.contr_p, kScaleGain);
  c.ti_ms = to_eu(in.contr_i, kScaleOne);
  c.slave_alpha_pct = s.cmd_source == CommandSource::Bus ? to_eu(in.slave_alpha, kScalePercent) : in.analog_slave;

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

SelectedCommands select_commands(const SetSelection& sel, const CardParameters& p, const AnalogInputs& analog,
                                 const Settings& s) {
  return convert_commands(gather_commands(sel, p, analog, s), s);
}

const SelectedCommands& CommandSelector::select(const SetSelection& sel, const CardParameters& p,
                                                const AnalogInputs& analog, const Settings& s) {
  const CommandInputs in = gather_commands(sel, p, analog, s);
  if (!valid_ || !in.same_as(last_)) {
    last_ = in;
    commands_ = convert_commands(in, s);
    valid_ = true;
  }
  return commands_;
}

}  // namespace vtvpcd
