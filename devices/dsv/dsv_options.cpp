#include "devices/dsv/dsv_options.h"

#include "devices/settings_reader.h"

namespace dsv {

std::string DsvOptions::read(const devices::DeviceOptions& options) {
  if (options.variant.empty() || options.variant == "amplifier") {
    variant = Variant::Amplifier;
  } else if (options.variant == "controller") {
    variant = Variant::Controller;
  } else {
    return "unknown DSV variant '" + options.variant + "' (amplifier, controller)";
  }
  if (options.node_id > 127) return "node-ID must be 1..127";
  node_id = options.node_id == 0 ? 1 : options.node_id;

  // The settings table: one line per setting (docs/devices/dsv.md, "Settings").
  devices::SettingsReader s(options.settings);
  common.read(s);
  s.get_integer("solenoids", solenoids);
  s.get_integer("supply_voltage_nominal", supply);
  s.get_integer("device_local", delivery_device_local);
  s.get_integer("control_mode", delivery_control_mode);
  s.get_integer("mode_of_operation", delivery_mode_of_operation);
  s.get_integer("imin", imin);
  s.get_integer("imax", imax);
  s.get_integer("imax_limit", imax_limit);
  s.get_integer("dither_frequency", dither_frequency);
  s.get_integer("dither_amplitude", dither_amplitude);
  s.get_integer("capability", capability);
  s.get("objects_follow_mode", objects_follow_mode);
  s.get("actual_value_writable", actual_value_writable);
  s.get("pdo_cobid_writable", pdo_cobid_writable);
  s.get("local_strict", local_strict);
  s.get("op_mode1_bipolar", op_mode1_bipolar);
  s.get("m4_tpdo_six_bytes", m4_tpdo_six_bytes);
  s.get("quantise_on_write", quantise_on_write);
  s.get("restore_keeps_address", restore_keeps_address);
  s.get("alias_230e_mode7", alias_230e_mode7);
  s.get("pdo_padding", pdo_padding);
  s.get("strict_fault_reset", strict_fault_reset);
  s.get("fault_hold", fault_hold);
  s.get("cable_break_ma", cable_break_ma);
  supply_min = supply == 12 ? 9.0 : 18.0;  // before the reading: the default follows the supply
  s.get("u_supply_min", supply_min);
  s.get("sensor_min", sensor_min);
  s.get("sensor_max", sensor_max);
  s.get("t_ambient", ambient_temperature);
  s.get("k_thermal", thermal_gain);
  if (auto e = s.finish(); !e.empty()) return e;
  if (options.warnings) options.warnings->insert(options.warnings->end(), s.warnings().begin(), s.warnings().end());

  if (solenoids != 1 && solenoids != 2) return "setting 'solenoids' must be 1 or 2";
  if (supply != 24 && supply != 12) return "setting 'supply_voltage_nominal' must be 24 or 12";
  if (delivery_device_local != 0 && delivery_device_local != 1) return "setting 'device_local' must be 0 or 1";
  if (delivery_mode_of_operation < 0 || delivery_mode_of_operation > 3 ||
      (solenoids == 1 && delivery_mode_of_operation != 0)) {
    return "setting 'mode_of_operation' is not possible with this hardware";
  }
  if (!(0 <= imin && imin <= imax && imax <= imax_limit && imax_limit <= 16384)) {
    return "valve currents need 0 <= imin <= imax <= imax_limit <= 16384";
  }
  if (dither_amplitude < 0 || dither_amplitude > 4266) return "setting 'dither_amplitude' must be 0..4266";
  if (!(sensor_max > sensor_min)) return "sensor_max must be above sensor_min";
  return {};
}

}  // namespace dsv
