#include "devices/profiles/wandfluh/communication.h"

namespace wandfluh {

using canopen::Access;
using canopen::DataType;
using canopen::SdoAbort;

void CommonOptions::read(devices::SettingsReader& s) {
  s.get_uint("error_history_depth", error_history_depth, 1, 254);
  s.get_uint("identity_entries", identity_entries, 1, 4);
  identity_entries = identity_entries == 4 ? 4 : 1;
  s.get("sdo_server_parameter", sdo_server_parameter);
  s.get("nmt_fault_from_init", nmt_fault_from_init);
  s.get_uint("life_guard_emcy", communication_emcy, 0, 0xFFFF);
  s.get("save_all_pdo_params", save_all_pdo_parameters);
  s.get_int("boot_delay_ms", boot_delay_ms, 0, 3'600'000);
  s.get("rtr_mirror_dlc", rtr_mirror_dlc);
  s.get_uint("sdo_unknown_command_abort", unknown_command_abort, 0, 0xFFFFFFFF);
  s.get("heartbeat_suspends_life_guarding", heartbeat_suspends_life_guarding);
  s.get("emcy_before_stop", emcy_before_stop);
  s.get("outputs_need_operational", outputs_need_operational);
  s.get("device_version", device_version, kMaxText);
  s.get("serial_number", serial_number, kMaxText);
  s.get("model_description", model_description, kMaxText);
  s.get("vendor_name", vendor_name, kMaxText);
}

canopen::CommunicationProfile communication_profile(std::uint32_t device_type, const CommonOptions& o) {
  canopen::CommunicationProfile p;
  p.device_type = device_type;
  p.vendor_id = kVendorId;
  p.identity_entries = o.identity_entries;  // product code, revision, serial: "none" → 0 when shown
  p.error_history_depth = o.error_history_depth;
  p.sync = true;
  p.guarding = true;
  p.store_groups = 3;
  p.emcy_cob_id = true;
  p.emcy_inhibit = false;       // 0x1015 only named in the COB-ID table
  p.heartbeat_consumers = 0;    // 0x1016 likewise
  p.heartbeat_producer = true;
  p.sdo_server_parameter = o.sdo_server_parameter;
  return p;
}

canopen::NodePolicy node_policy(const CommonOptions& o, const std::string& store_path) {
  canopen::NodePolicy p;
  p.sdo.pad_short_requests = false;
  p.sdo.size_mode = canopen::SdoPolicy::SizeMode::Strict;
  p.sdo.unknown_command = static_cast<SdoAbort>(o.unknown_command_abort);
  p.sdo.timeout = sim::Duration{0};  // 0x05040000 is not in the manuals' abort list
  p.nmt.require_dlc_2 = true;
  p.nmt.boot_delay = sim::milliseconds(o.boot_delay_ms);
  p.nmt.reset_delay = sim::milliseconds(o.boot_delay_ms);
  p.error_control.guard_while_heartbeat = true;
  p.error_control.life_guard_emcy = 0;  // the device raises 0x8100 itself, with its fault reaction
  p.error_control.communication_error_register = 0x11;
  p.emcy.history = canopen::EmcyPolicy::History::Events;
  p.emcy.history_depth = o.error_history_depth;
  p.emcy.send_no_error = true;
  p.emcy.record_when_not_sent = true;
  p.emcy.clear_history_on_reset_communication = true;
  p.emcy.history_write_nonzero = SdoAbort::ParameterIncompatible;
  p.emcy.history_read_beyond = SdoAbort::NoSubIndex;
  p.pdo.type254 = {.on_change = true, .after_rpdo = false, .on_timer = false};
  p.pdo.type255 = {.on_change = false, .after_rpdo = true, .on_timer = false};
  p.pdo.send_async_on_operational = false;
  p.pdo.rtr_dlc_mismatch = o.rtr_mirror_dlc ? canopen::PdoPolicy::RtrDlcMismatch::Answer
                                            : canopen::PdoPolicy::RtrDlcMismatch::EmptyFrame;
  p.pdo.rpdo_length_emcy = false;  // 0x8210 is not in the devices' EMCY lists
  p.pdo.rpdo_too_long_is_error = false;
  p.pdo.rpdo_types.reset();
  for (int t = 0; t <= 240; ++t) p.pdo.rpdo_types.set(static_cast<std::size_t>(t));
  p.pdo.rpdo_types.set(255);  // 252/253 are RTR-only, 254 "only for TPDOs"
  p.pdo.tpdo_types = canopen::PdoPolicy::default_tpdo_types();
  p.pdo.bad_transmission_type = SdoAbort::ParameterIncompatible;
  p.pdo.sync_requires_dlc0 = false;
  p.pdo.sync_producer_refused = SdoAbort::ParameterIncompatible;
  p.store.wrong_signature = SdoAbort::DataTransfer;
  p.store.restore = canopen::StorePolicy::Restore::PendingUntilReset;
  p.store.path = store_path;
  p.store.groups = {{1, {{0x1000, 0xFFFF}}}, {2, {{0x1000, 0x1FFF}}}, {3, {{0x2000, 0x9FFF}}}};
  return p;
}

void install_guarding_lock(canopen::ObjectDictionary& od) {
  for (std::uint16_t index : {std::uint16_t{0x100C}, std::uint16_t{0x100D}}) {
    od.add_check(
        index, 0,
        [&od](const canopen::OdEntry&, std::span<std::uint8_t>, canopen::Origin origin) {
          if (origin == canopen::Origin::Sdo && od.get<std::uint16_t>(0x1017) != 0) return SdoAbort::ResourceUnavailable;
          return SdoAbort::None;
        },
        canopen::CheckStage::State);
  }
}

void add_device_strings(canopen::ObjectDictionary& od, const CommonOptions& o) {
  using canopen::ObjectDictionary;
  od.add_var(0x6050, "Device version", DataType::VisibleString, Access::ReadOnly,
             ObjectDictionary::encode(DataType::VisibleString, o.device_version));
  od.add_var(0x6052, "Device serial number", DataType::VisibleString, Access::ReadOnly,
             ObjectDictionary::encode(DataType::VisibleString, o.serial_number));
  od.add_var(0x6054, "Device model description", DataType::VisibleString, Access::ReadOnly,
             ObjectDictionary::encode(DataType::VisibleString, o.model_description));
  od.add_var(0x6057, "Device vendor name", DataType::VisibleString, Access::ReadOnly,
             ObjectDictionary::encode(DataType::VisibleString, o.vendor_name));
}

void mark_saved_communication_entries(canopen::ObjectDictionary& od, bool all_pdo_parameters) {
  auto saved = [all_pdo_parameters](std::uint16_t index, std::uint8_t sub) {
    switch (index) {
      case 0x1005:
      case 0x100C:
      case 0x100D:
      case 0x1014:
      case 0x1017: return true;
      case 0x1400:
      case 0x1401:
      case 0x1800: return sub == 1 || sub == 2;
      default: break;
    }
    if (all_pdo_parameters && ((index >= 0x1400 && index <= 0x15FF) || (index >= 0x1800 && index <= 0x19FF))) {
      return sub >= 1;
    }
    return false;
  };
  for (const auto& [index, object] : od.objects()) {
    if (index < 0x1000 || index > 0x1FFF) continue;
    for (const auto& [sub, e] : object.entries) {
      od.entry(index, sub)->persistent = saved(index, sub);
    }
  }
}

}  // namespace wandfluh
