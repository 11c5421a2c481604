#include "devices/wdga/wdga_settings.h"

#include "devices/profiles/cia406/scripted_input.h"
#include "devices/settings_reader.h"

namespace wdga {

std::string parse_settings(const std::string& variant, const std::map<std::string, std::string>& text, Settings& s) {
  if (variant == "multiturn" || variant.empty()) {
    s.multiturn = true;
  } else if (variant == "singleturn") {
    s.multiturn = false;
  } else {
    return "unknown variant '" + variant + "' (variants: multiturn, singleturn)";
  }
  devices::SettingsReader r(text);
  r.get_uint("revision", s.revision, 0, 0xFFFFFFFF);
  r.get_uint("serial", s.serial, 0, 0xFFFFFFFF);
  r.get("hardware_version", s.hardware_version, 2);
  r.get("hardware_version_4_bytes", s.hardware_version_4_bytes);
  r.get("software_version", s.software_version, 9);
  r.get_uint("profile_software_version", s.profile_software_version, 0, 0xFFFFFFFF);
  r.get("is_32bit_variant", s.is_32bit_variant);
  r.get_uint("factory_total_range", s.factory_total_range, 0, 0xFFFFFFFF);
  r.get_uint("total_range_max", s.total_range_max, 1, 0xFFFFFFFF);
  r.get_uint("factory_node_id", s.factory_node_id, 1, 127);
  r.get_uint("factory_bit_rate", s.factory_bit_rate, 0, 9);
  r.get("tpdo3_literal_mapping", s.tpdo3_literal_mapping);
  r.get("cobid_no_rtr_bit", s.cobid_no_rtr_bit);
  r.get("cyclic_timer_alias", s.cyclic_timer_alias);
  r.get("initial_tpdo", s.initial_tpdo);
  r.get("error_history_count_u32", s.error_history_count_u32);
  int units = s.speed_physical_units ? 1 : 0;
  r.choose("speed_units", units, {"scaled", "physical"});
  s.speed_physical_units = units == 1;
  r.get_uint("position_error_emcy", s.position_error_emcy, 0, 0xFFFF);
  r.get("strict_cobid", s.strict_cobid);
  r.get("restore_at_once", s.restore_at_once);
  r.get("bus_warning_emcy", s.bus_warning_emcy);
  r.get_uint("temperature_period_s", s.temperature_period_s, 1, 3600);
  r.get_uint("boot_delay_ms", s.boot_delay_ms, 0, 60000);
  r.get("signal", s.signal, 200);
  if (auto e = r.finish(); !e.empty()) return e;
  if (!s.multiturn && s.is_32bit_variant) return "setting is_32bit_variant: a singleturn WDGA has at most 16384 steps";
  const std::uint32_t tmr = s.default_total_range();
  if (tmr == 0 && !s.is_32bit_variant) return "setting factory_total_range: 0 (2^32) needs is_32bit_variant=on";
  if (!s.multiturn && tmr > 0x4000) return "setting factory_total_range: a singleturn WDGA has at most 16384 steps";
  cia406::ScriptedInput probe;
  if (auto e = probe.parse(s.signal); !e.empty()) return "setting signal: " + e;
  return {};
}

}  // namespace wdga
