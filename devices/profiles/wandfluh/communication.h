// The CANopen behaviour the Wandfluh DSP 408 electronics (MD2, DSV) share. Both manuals print the
// same communication chapters; where their two digests read the same text differently, the
// choice made here holds for both products (docs/devices/md2.md, "Choices shared with the DSV"):
//   unknown SDO command specifier → 0x08000000 (the manuals' abort list has no 0x05040001);
//   non-zero write to 0x1003:00 → 0x06040043 ("value invalid");
//   0x1003 depth 254 (the printed range), reading beyond the count → 0x06090011;
//   0x1018:00 = 1 and sub-indices 2..4 absent (0x06090011);
//   TPDO type 0: sent at a SYNC when the mapped data changed (first SYNC always);
//   TPDO type 254: sent when the mapped data change; type 255: right after its RPDO;
//   save list exactly as printed; life guarding not supervised while a heartbeat is produced.
#pragma once

#include <cstdint>
#include <string>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/standard_objects.h"
#include "devices/settings_reader.h"

namespace wandfluh {

constexpr std::uint32_t kVendorId = 0x0000014D;

/// Knobs common to both products (DeviceOptions::settings names in comments).
struct CommonOptions {
  std::uint8_t error_history_depth = 254;           ///< error_history_depth
  std::uint8_t identity_entries = 1;                ///< identity_entries (1 or 4)
  bool sdo_server_parameter = false;                ///< sdo_server_parameter: 0x1200 read-only
  bool nmt_fault_from_init = false;                 ///< nmt_fault_from_init
  std::uint16_t communication_emcy = 0x8100;        ///< life_guard_emcy (0x8100 or 0x8130)
  bool save_all_pdo_parameters = false;             ///< save_all_pdo_params
  std::int64_t boot_delay_ms = 0;                   ///< boot_delay_ms
  bool rtr_mirror_dlc = false;                      ///< rtr_mirror_dlc: answer a wrong-DLC RTR with data
  std::uint32_t unknown_command_abort = 0x08000000; ///< sdo_unknown_command_abort
  bool heartbeat_suspends_life_guarding = true;     ///< heartbeat_suspends_life_guarding
  bool emcy_before_stop = false;   ///< emcy_before_stop: the 0x8100 of NMT Stop goes out before Stopped
  bool outputs_need_operational = false;  ///< outputs_need_operational: 0 A outside NMT Operational
  // Identity strings (0x6050, 0x6052, 0x6054, 0x6057): the manuals' example values.
  std::string device_version = "V1.0.0.0";          ///< device_version
  std::string serial_number = "123.4567";           ///< serial_number
  std::string model_description = "Valve type";     ///< model_description
  std::string vendor_name = "Wandfluh AG";          ///< vendor_name

  /// Longest identity string accepted (a VISIBLE_STRING read by SDO segments).
  static constexpr std::size_t kMaxText = 255;

  void read(devices::SettingsReader& s);
};

/// 0x1000-0x1018 as both manuals list them.
canopen::CommunicationProfile communication_profile(std::uint32_t device_type, const CommonOptions& o);
/// Stack policy for both products (PDO details are completed by each product).
canopen::NodePolicy node_policy(const CommonOptions& o, const std::string& store_path);

/// 0x100C/0x100D are refused with 0x060A0023 while a heartbeat is produced (§5.4.8/9).
void install_guarding_lock(canopen::ObjectDictionary& od);
/// Device version, serial number, model description, vendor name (0x6050..0x6057).
void add_device_strings(canopen::ObjectDictionary& od, const CommonOptions& o);
/// The printed save list (§5.4.10): only these communication entries are stored, unless all PDO
/// parameters are (option); everything else in 0x1000-0x1FFF is volatile.
void mark_saved_communication_entries(canopen::ObjectDictionary& od, bool all_pdo_parameters);

}  // namespace wandfluh
