// The WDGA's configuration: the variant (multiturn / singleturn), per-device identity values
// ("i*" in the manual), and every [R] reading of the digest that changes what the bus sees, each
// with the digest's default. docs/devices/wdga.md lists them.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace wdga {

struct Settings {
  bool multiturn = true;
  // Identity (per device).
  std::uint32_t revision = 0x03060208;
  std::uint32_t serial = 0x00BC6138;
  std::string hardware_version = "AA";
  bool hardware_version_4_bytes = false;  ///< "AA" as 4 bytes 41 41 00 00 (A-33)
  std::string software_version = "2.08";
  std::uint32_t profile_software_version = 0x01050302;  ///< 6507h (A-23)
  // Ordered variant.
  bool is_32bit_variant = false;          ///< 6002h = 0 means 2^32 (only here)
  std::uint32_t factory_total_range = 0;  ///< 0 = variant default (MT 2^30, ST 16384)
  std::uint32_t total_range_max = 0xFFFFFFFF;  ///< A-21 (alternative 0x80000000)
  std::uint8_t factory_node_id = 127;
  std::uint8_t factory_bit_rate = 9;  ///< table index; 9 = automatic detection
  // Readings of the manual ([R]).
  bool tpdo3_literal_mapping = false;   ///< 1A02h:01 = 0x60080020 as printed (A-8)
  bool cobid_no_rtr_bit = true;         ///< TPDO COB-IDs read back with bit 30 set (A-27)
  bool cyclic_timer_alias = false;      ///< 6200h mirrors 1800h:05 instead of pacing TPDO1 (A-15)
  bool initial_tpdo = true;             ///< event-driven TPDOs once on entering Operational
  /// 2502h:00 as the UNSIGNED32 the table prints. Off by default: CiA 301 requires
  /// UNSIGNED8 for a sub-index 0 (the EDS would not be conformant), as 2503h/2504h have it.
  bool error_history_count_u32 = false;
  bool speed_physical_units = false;    ///< speed in physical steps (16384/rev) instead of scaled (A-22)
  std::uint16_t position_error_emcy = 0;  ///< EMCY code for 6503h bit 0 (0 = none; A-37 suggests 0x1000)
  bool strict_cobid = false;            ///< TPDO COB-IDs in CiA 301's restricted ranges abort
  bool restore_at_once = false;         ///< 1011h "load" applies the defaults at once, not at the next reset (A-39)
  bool bus_warning_emcy = true;         ///< EMCY 8100h for bus warning and back to error-active (A-32)
  unsigned temperature_period_s = 60;
  unsigned boot_delay_ms = 0;
  std::string signal = "hold";          ///< scripted shaft angle for standalone runs (rad, rad/s)

  std::uint32_t default_total_range() const {
    if (factory_total_range != 0 || is_32bit_variant) return factory_total_range;
    return multiturn ? 0x40000000u : 0x4000u;
  }
};

/// Parses the variant and DeviceOptions::settings; returns an error message, empty if fine.
std::string parse_settings(const std::string& variant, const std::map<std::string, std::string>& text, Settings& out);

}  // namespace wdga
