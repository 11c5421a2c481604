// The HLT 1100's configuration: the values the manual leaves open (identity, nameplate length,
// factory node-ID and bit rate) and every [REC] reading of the digest that changes what the bus
// sees, each with the digest's default. docs/devices/hlt1100.md lists them.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace hlt1100 {

struct Settings {
  // Identity and nameplate.
  std::uint32_t product_code = 0x00001100;
  std::uint32_t revision = 0x00010004;
  std::uint32_t serial = 0x00000001;
  std::string device_name = "HLT1100";
  std::string hardware_version = "01.00";
  std::string software_version = "01.04";
  std::uint16_t software_version_bcd = 0x0104;  ///< 6507h high word
  double measuring_length_mm = 500.0;
  std::int32_t manufacturer_offset = 0;         ///< 650Ah:01
  std::int32_t manufacturer_min = 0;            ///< 650Ah:02
  std::int64_t manufacturer_max = -1;           ///< 650Ah:03; -1 = steps − 1
  std::uint32_t speed_step = 10;                ///< 6005h:02, units of 0.01 mm/s

  // Factory bus settings (LSS only on the device).
  std::uint8_t node_id = 1;  ///< factory node-ID (setting factory_node_id; 255 = unconfigured)
  unsigned bit_rate_kbit = 250;

  // Timing.
  unsigned sample_period_ms = 1;
  unsigned speed_window_ms = 16;
  unsigned save_delay_ms = 3000;
  unsigned boot_delay_ms = 0;

  // Readings of the manual ([REC]).
  std::uint16_t position_emcy_code = 0xFF00;
  bool error_register_generic_bit = true;  ///< ER 0x21/0x11 (on) or 0x20/0x10 (off)
  bool hold_last_on_error = true;          ///< 6020h keeps the last valid value (off: 0)
  bool dynamic_mapping = false;
  bool parameter_error_abort = false;      ///< out-of-range 6000h/6010h: abort instead of alarm bit 13
  bool nmt_startup_prose = false;          ///< 1F80h bit 2 = 1 means autostart (the manual's prose)
  bool lss_fastscan_configured = false;    ///< fastscan also for configured nodes
  bool lss_in_operational = true;
  bool lss_store_before_waiting = true;    ///< CiA 305 transition 4 needs "store"
  unsigned lss_store_delay_ms = 0;         ///< LSS "store configuration" answered after this, silent meanwhile (§6 #34)
  bool sync_dlc_strict = true;             ///< only SYNC with DLC 0 triggers TPDO2
  bool reset_node_factory = false;         ///< Reset Node loads factory values (off: stored values)
  bool preset_auto_save = false;           ///< a preset is saved at once (off: only with 1010h)
  std::uint16_t supported_alarms = 0x3001; ///< 6504h
  std::uint32_t eeprom_abort = 0x06060000; ///< SDO abort of a failed save/restore
  std::uint16_t life_guard_emcy = 0;       ///< EMCY code on a life-guarding timeout (0 = none)
  std::string signal = "hold";             ///< scripted position input for standalone runs

  /// Measuring length in steps of 0.1 mm.
  std::int64_t steps() const;
};

/// Parses DeviceOptions::settings over the defaults; returns an error message, empty if fine.
std::string parse_settings(const std::map<std::string, std::string>& text, Settings& out);

}  // namespace hlt1100
