#include "devices/md2/md2_options.h"

#include <cmath>
#include <numbers>

#include "devices/settings_reader.h"

namespace md2 {

namespace {
// Longest unit name or speed-mode list accepted.
constexpr std::size_t kMaxListText = 64;
}  // namespace

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

  // The settings table: one line per setting (docs/devices/md2.md, "Settings"). The names the
  // DSV shares are the DSV's; the MD2's older spellings still work, with a warning.
  devices::SettingsReader s(options.settings);
  s.deprecated("nv_control_mode", "control_mode");
  s.deprecated("dither_freq", "dither_frequency");
  common.read(s);
  s.get_integer("channels", channels);
  delivery_control_mode = variant == Variant::Amplifier ? 1 : 3;
  s.get_integer("control_mode", delivery_control_mode);
  s.get_integer("solenoids", solenoids);
  s.get("i_min_a", i_min_a);
  s.get("i_max_a", i_max_a);
  s.get("i_min_b", i_min_b);
  s.get("i_max_b", i_max_b);
  s.get("i_limit", i_limit);
  s.get("dither_frequency", dither_frequency);
  s.get("dither_level", dither_level);
  int dither_shape = dither_sine ? 1 : 0;
  s.choose("dither_shape", dither_shape, {"square", "sine"});
  dither_sine = dither_shape == 1;
  s.get("deadband", deadband);
  s.get("ramp_up_ms", ramp_up_ms);
  s.get("ramp_down_ms", ramp_down_ms);
  s.get("bus_full_scale", bus_full_scale);
  std::string unit_name = unit.name;
  s.get("unit", unit_name, kMaxListText);
  s.get("setpoint_min", setpoint_min);
  s.get("p_range", p_range);
  s.get("kp", kp);
  s.get("ki", ki);
  s.get("kd", kd);
  s.get("kff", kff);
  s.get("window", window);
  s.get("window_scaled", window_scaled);
  s.get("hysteresis", hysteresis);
  s.get("u_supply_min", supply_min);
  s.get("t_ambient", ambient_temperature);
  s.get("k_thermal", thermal_gain);
  s.get_integer("capability", capability);
  s.get_integer("device_type", device_type);
  s.get("vpoc_mapping_literal", vpoc_mapping_literal);
  s.get("tpdo_actual_value", tpdo_actual_value);
  s.get("pdo_params_preop_only", pdo_params_preop_only);
  s.get_integer("identity_revision", identity_revision);
  s.get_integer("identity_serial", identity_serial);
  s.get("tpdo255_on_change", tpdo255_on_change);
  std::string speed_list = "6,7,9";
  s.get("speed_modes", speed_list, kMaxListText);
  int deadband_modes = deadband_all_modes ? 0 : 1;
  s.choose("deadband_modes", deadband_modes, {"all", "open_loop"});
  deadband_all_modes = deadband_modes == 0;
  if (!find_unit(unit_name, unit)) return "setting 'unit': unknown unit '" + unit_name + "'";
  setpoint_max = unit.max;  // the default follows the unit
  s.get("setpoint_max", setpoint_max);
  if (auto e = s.finish(); !e.empty()) return e;
  if (options.warnings) options.warnings->insert(options.warnings->end(), s.warnings().begin(), s.warnings().end());

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
