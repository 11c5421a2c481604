#include "devices/dsv/dsv_options.h"

#include "devices/profiles/wandfluh/settings.h"

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

  wandfluh::Settings s(options.settings);
  common.read(s);
  solenoids = static_cast<int>(s.integer("solenoids", solenoids));
  supply = static_cast<int>(s.integer("supply_voltage_nominal", supply));
  delivery_device_local = static_cast<std::int8_t>(s.integer("device_local", delivery_device_local));
  delivery_control_mode = static_cast<std::int8_t>(s.integer("control_mode", delivery_control_mode));
  delivery_mode_of_operation = static_cast<std::int8_t>(s.integer("mode_of_operation", delivery_mode_of_operation));
  imin = static_cast<std::int32_t>(s.integer("imin", imin));
  imax = static_cast<std::int32_t>(s.integer("imax", imax));
  imax_limit = static_cast<std::int32_t>(s.integer("imax_limit", imax_limit));
  dither_frequency = static_cast<std::int16_t>(s.integer("dither_frequency", dither_frequency));
  dither_amplitude = static_cast<std::int16_t>(s.integer("dither_amplitude", dither_amplitude));
  capability = static_cast<std::uint32_t>(s.integer("capability", 0));
  objects_follow_mode = s.flag("objects_follow_mode", objects_follow_mode);
  actual_value_writable = s.flag("actual_value_writable", actual_value_writable);
  pdo_cobid_writable = s.flag("pdo_cobid_writable", pdo_cobid_writable);
  local_strict = s.flag("local_strict", local_strict);
  op_mode1_bipolar = s.flag("op_mode1_bipolar", op_mode1_bipolar);
  m4_tpdo_six_bytes = s.flag("m4_tpdo_six_bytes", m4_tpdo_six_bytes);
  quantise_on_write = s.flag("quantise_on_write", quantise_on_write);
  restore_keeps_address = s.flag("restore_keeps_address", restore_keeps_address);
  alias_230e_mode7 = s.flag("alias_230e_mode7", alias_230e_mode7);
  pdo_padding = s.flag("pdo_padding", pdo_padding);
  strict_fault_reset = s.flag("strict_fault_reset", strict_fault_reset);
  fault_hold = s.flag("fault_hold", fault_hold);
  cable_break_ma = s.number("cable_break_ma", cable_break_ma);
  supply_min = s.number("u_supply_min", supply == 12 ? 9.0 : 18.0);
  sensor_min = s.number("sensor_min", sensor_min);
  sensor_max = s.number("sensor_max", sensor_max);
  ambient_temperature = s.number("t_ambient", ambient_temperature);
  thermal_gain = s.number("k_thermal", thermal_gain);
  if (auto e = s.finish(); !e.empty()) return e;

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
