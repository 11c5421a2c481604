#include "devices/md2/md2_options.h"

#include <cmath>
#include <numbers>

#include "devices/profiles/wandfluh/settings.h"

namespace md2 {

bool find_unit(const std::string& name, Unit& out) {
  constexpr double kDeg = std::numbers::pi / 180;
  static const Unit kUnits[] = {
      {"bar", 1e5, 500000},       {"psi", 6894.757293168, 8000000}, {"kN", 1e3, 1000000},
      {"MPa", 1e6, 50000},        {"l/min", 1e-3 / 60, 500000},    {"mm/s", 1e-3, 2000000},
      {"inch/s", 0.0254, 10000000}, {"1/min", 2 * std::numbers::pi / 60, 100000}, {"deg/s", kDeg, 360000},
      {"mm", 1e-3, 2000000},      {"deg", kDeg, 360000},           {"inch", 0.0254, 100000},
  };
  for (const auto& u : kUnits) {
    if (u.name == name) {
      out = u;
      return true;
    }
  }
  return false;
}

std::string Md2Options::read(const devices::DeviceOptions& options) {
  if (options.variant.empty() || options.variant == "amplifier") {
    variant = Variant::Amplifier;
  } else if (options.variant == "controller") {
    variant = Variant::Controller;
  } else {
    return "unknown MD2 variant '" + options.variant + "' (amplifier, controller)";
  }
  if (options.node_id > 127) return "node-ID must be 1..127";
  node_id = options.node_id == 0 ? 1 : options.node_id;

  wandfluh::Settings s(options.settings);
  common.read(s);
  channels = static_cast<int>(s.integer("channels", 8));
  delivery_control_mode =
      static_cast<std::int8_t>(s.integer("nv_control_mode", variant == Variant::Amplifier ? 1 : 3));
  solenoids = static_cast<int>(s.integer("solenoids", 2));
  i_min_a = s.number("i_min_a", i_min_a);
  i_max_a = s.number("i_max_a", i_max_a);
  i_min_b = s.number("i_min_b", i_min_b);
  i_max_b = s.number("i_max_b", i_max_b);
  i_limit = s.number("i_limit", i_limit);
  dither_frequency = s.number("dither_freq", dither_frequency);
  dither_level = s.number("dither_level", dither_level);
  dither_sine = s.choice("dither_shape", "square", {"square", "sine"}) == "sine";
  deadband = s.number("deadband", deadband);
  ramp_up_ms = s.number("ramp_up_ms", ramp_up_ms);
  ramp_down_ms = s.number("ramp_down_ms", ramp_down_ms);
  bus_full_scale = s.number("bus_full_scale", bus_full_scale);
  const std::string unit_name = s.text("unit", "mm");
  setpoint_min = s.number("setpoint_min", setpoint_min);
  p_range = s.number("p_range", p_range);
  kp = s.number("kp", kp);
  ki = s.number("ki", ki);
  kd = s.number("kd", kd);
  kff = s.number("kff", kff);
  window = s.number("window", window);
  window_scaled = s.number("window_scaled", window_scaled);
  hysteresis = s.number("hysteresis", hysteresis);
  supply_min = s.number("u_supply_min", supply_min);
  ambient_temperature = s.number("t_ambient", ambient_temperature);
  thermal_gain = s.number("k_thermal", thermal_gain);
  capability = static_cast<std::uint32_t>(s.integer("capability", 0));
  device_type = static_cast<std::uint32_t>(s.integer("device_type", 0x10000198));
  vpoc_mapping_literal = s.flag("vpoc_mapping_literal", false);
  tpdo_actual_value = s.flag("tpdo_actual_value", true);
  pdo_params_preop_only = s.flag("pdo_params_preop_only", true);
  identity_revision = static_cast<std::uint32_t>(s.integer("identity_revision", 0));
  identity_serial = static_cast<std::uint32_t>(s.integer("identity_serial", 0));
  tpdo255_on_change = s.flag("tpdo255_on_change", false);
  const std::string speed_list = s.text("speed_modes", "6,7,9");
  deadband_all_modes = s.choice("deadband_modes", "all", {"all", "open_loop"}) == "all";
  if (!find_unit(unit_name, unit)) return "setting 'unit': unknown unit '" + unit_name + "'";
  setpoint_max = s.number("setpoint_max", unit.max);
  if (auto e = s.finish(); !e.empty()) return e;

  speed_modes.clear();
  for (std::size_t pos = 0; pos < speed_list.size();) {
    std::size_t end = speed_list.find(',', pos);
    if (end == std::string::npos) end = speed_list.size();
    const std::string item = speed_list.substr(pos, end - pos);
    pos = end + 1;
    if (item.empty()) continue;
    std::size_t used = 0;
    int m = 0;
    try {
      m = std::stoi(item, &used);
    } catch (...) {
      used = 0;
    }
    // Modes 1 and 3 have their ramp, 0 drives nothing: Speed± can only apply to the others.
    if (used != item.size() || !(m == 4 || m == 6 || m == 7 || m == 9 || (m >= -8 && m <= -5))) {
      return "setting 'speed_modes': '" + item + "' is not a control mode with a set point to limit (4, 6, 7, 9, -5..-8)";
    }
    speed_modes.push_back(static_cast<std::int8_t>(m));
  }
  if (channels < 1 || channels > 8) return "setting 'channels' must be 1..8";
  if (solenoids != 1 && solenoids != 2) return "setting 'solenoids' must be 1 or 2";
  if (!(i_min_a >= 0 && i_min_a <= i_max_a && i_min_b >= 0 && i_min_b <= i_max_b)) {
    return "solenoid currents need 0 <= i_min <= i_max";
  }
  if (!(i_limit >= i_max_a && i_limit >= i_max_b)) return "setting 'i_limit' must be >= i_max_a and i_max_b";
  if (!(bus_full_scale > 0 && bus_full_scale <= 32767)) return "setting 'bus_full_scale' must be 1..32767";
  if (!(setpoint_max > setpoint_min)) return "setpoint_max must be above setpoint_min";
  if (!(p_range > 0)) return "setting 'p_range' must be > 0";
  if (ramp_up_ms < 0 || ramp_down_ms < 0 || deadband < 0 || dither_frequency < 0 || dither_level < 0) {
    return "ramps, dead band and dither must not be negative";
  }
  return {};
}

}  // namespace md2
