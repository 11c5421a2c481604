#include "devices/hlt1100/hlt1100_settings.h"

#include <cmath>

#include "devices/profiles/cia406/scripted_input.h"
#include "devices/settings_reader.h"

namespace hlt1100 {

std::int64_t Settings::steps() const { return static_cast<std::int64_t>(std::llround(measuring_length_mm * 10.0)); }

std::string parse_settings(const std::map<std::string, std::string>& text, Settings& s) {
  devices::SettingsReader r(text);
  r.get_uint("product_code", s.product_code, 0, 0xFFFFFFFF);
  r.get_uint("revision", s.revision, 0, 0xFFFFFFFF);
  r.get_uint("serial", s.serial, 0, 0xFFFFFFFF);
  r.get("device_name", s.device_name, 64);
  r.get("hardware_version", s.hardware_version, 64);
  r.get("software_version", s.software_version, 64);
  r.get_uint("software_version_bcd", s.software_version_bcd, 0, 0xFFFF);
  r.get("measuring_length_mm", s.measuring_length_mm, 0.2, 20000.0);
  r.get_int("manufacturer_offset", s.manufacturer_offset, INT32_MIN, INT32_MAX);
  r.get_int("manufacturer_min", s.manufacturer_min, INT32_MIN, INT32_MAX);
  r.get_int("manufacturer_max", s.manufacturer_max, -1, INT32_MAX);
  r.get_uint("speed_step", s.speed_step, 1, 0xFFFFFFFF);
  r.get_uint("factory_node_id", s.node_id, 1, 255);
  std::uint64_t kbit = s.bit_rate_kbit;
  r.get("bit_rate_kbit", kbit, 0, 1000);
  s.bit_rate_kbit = static_cast<unsigned>(kbit);
  r.get_uint("sample_period_ms", s.sample_period_ms, 1, 100);
  r.get_uint("speed_window_ms", s.speed_window_ms, 1, 1000);
  r.get_uint("save_delay_ms", s.save_delay_ms, 0, 60000);
  r.get_uint("boot_delay_ms", s.boot_delay_ms, 0, 60000);
  r.get_uint("position_emcy_code", s.position_emcy_code, 0x0001, 0xFFFF);
  r.get("error_register_generic_bit", s.error_register_generic_bit);
  r.get("hold_last_on_error", s.hold_last_on_error);
  r.get("dynamic_mapping", s.dynamic_mapping);
  int param = s.parameter_error_abort ? 1 : 0;
  r.choose("parameter_error", param, {"alarm", "abort"});
  s.parameter_error_abort = param == 1;
  int startup = s.nmt_startup_prose ? 1 : 0;
  r.choose("nmt_startup_bit2", startup, {"table", "prose"});
  s.nmt_startup_prose = startup == 1;
  r.get("lss_fastscan_configured", s.lss_fastscan_configured);
  r.get("lss_in_operational", s.lss_in_operational);
  r.get("lss_store_before_waiting", s.lss_store_before_waiting);
  r.get_uint("lss_store_delay_ms", s.lss_store_delay_ms, 0, 3000);
  r.get("sync_dlc_strict", s.sync_dlc_strict);
  int reset = s.reset_node_factory ? 1 : 0;
  r.choose("reset_node_loads", reset, {"stored", "factory"});
  s.reset_node_factory = reset == 1;
  r.get("preset_auto_save", s.preset_auto_save);
  r.get_uint("supported_alarms", s.supported_alarms, 0, 0xFFFF);
  int eeprom = s.eeprom_abort == 0x06000006 ? 1 : 0;
  r.choose("eeprom_abort", eeprom, {"0x06060000", "0x06000006"});
  s.eeprom_abort = eeprom == 1 ? 0x06000006 : 0x06060000;
  r.get_uint("life_guard_emcy", s.life_guard_emcy, 0, 0xFFFF);
  r.get("signal", s.signal, 200);
  if (auto e = r.finish(); !e.empty()) return e;
  static constexpr unsigned kRates[] = {1000, 800, 500, 250, 125, 50, 20};
  bool rate_ok = false;
  for (unsigned k : kRates) rate_ok = rate_ok || k == s.bit_rate_kbit;
  if (!rate_ok) return "setting bit_rate_kbit=" + std::to_string(s.bit_rate_kbit) + ": the HLT 1100 supports 20, 50, 125, 250, 500, 800, 1000";
  if (s.node_id > 127 && s.node_id != 255) return "setting factory_node_id: 1..127, or 255 for an unconfigured sensor";
  if (s.manufacturer_max > 0 && s.manufacturer_max < s.manufacturer_min) return "setting manufacturer_max: below manufacturer_min";
  cia406::ScriptedInput probe;
  if (auto e = probe.parse(s.signal); !e.empty()) return "setting signal: " + e;
  return {};
}

}  // namespace hlt1100
