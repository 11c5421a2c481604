#include "devices/vtvpcd/communication.h"

namespace vtvpcd {

namespace {
using canopen::NmtState;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

constexpr std::uint32_t kExtendedBit = 0x20000000u;
constexpr std::uint32_t kRtrOrProducerBit = 0x40000000u;

/// An 11-bit identifier is all the card knows (CAN 2.0A; the glossary: "COB-ID has 11 bits").
bool standard_identifier(std::uint32_t v) { return !(v & kExtendedBit) && !(v & 0x1FFFF800u); }

void add_state_check(canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub, canopen::WriteCheck check) {
  if (od.entry(index, sub)) od.add_check(index, sub, std::move(check), canopen::CheckStage::State);
}
}  // namespace

canopen::NodePolicy make_policy(const Settings& s) {
  canopen::NodePolicy p;
  // SDO (manual §3.3; A12-A14): short requests padded with zeros, expedited transfers only.
  p.sdo.pad_short_requests = true;
  p.sdo.size_mode = s.sdo_size_strict ? canopen::SdoPolicy::SizeMode::Strict : canopen::SdoPolicy::SizeMode::Lenient;
  p.sdo.unknown_command = SdoAbort::InvalidCommand;
  p.sdo.segmented_download = false;
  p.sdo.timeout = sim::Duration{0};  // 0x05040000 is not in the manual's abort table

  // NMT (manual §3.1; A4).
  p.nmt.require_dlc_2 = true;
  p.nmt.stop_supported = s.nmt_stop_supported;
  p.nmt.boot_delay = sim::milliseconds(s.boot_delay_ms);
  p.nmt.reset_delay = sim::milliseconds(s.reset_boot_delay_ms);

  // Error control: heartbeat replaces guarding (A20); the device raises fault 16 itself (A21).
  p.error_control.guard_while_heartbeat = false;
  p.error_control.life_guard_emcy = 0;
  p.error_control.heartbeat_consumer_emcy = 0;
  p.error_control.communication_error_register = 0x11;

  // EMCY (manual §3.5; A22, A23): 0x1003 lists the errors present now, at most 4.
  p.emcy.history = canopen::EmcyPolicy::History::PresentErrors;
  p.emcy.history_depth = 4;
  p.emcy.send_no_error = true;
  p.emcy.send_in_preoperational = s.emcy_in_preoperational;
  p.emcy.history_write_nonzero = SdoAbort::ValueTooHigh;
  p.emcy.history_read_beyond = SdoAbort::NoSubIndex;

  // PDO (manual §3.4; A16, A19): event-timer transmission only, no RTR, no SYNC, width
  // conversion for objects placed as 2 or 4 bytes, short RPDOs ignored without EMCY.
  const canopen::PdoPolicy::AsyncTriggers timer_only{.on_change = false, .after_rpdo = false, .on_timer = true};
  p.pdo.type254 = timer_only;
  p.pdo.type255 = timer_only;
  p.pdo.send_async_on_operational = false;
  p.pdo.tpdo_remote_requests = false;
  p.pdo.event_timer_restart_on_write = true;
  p.pdo.rpdo_length_emcy = false;
  p.pdo.rpdo_too_long_is_error = false;
  p.pdo.rpdo_types.reset();
  p.pdo.tpdo_types.reset();
  for (auto* types : {&p.pdo.rpdo_types, &p.pdo.tpdo_types}) {
    types->set(0xFE);
    types->set(0xFF);
  }
  p.pdo.bad_transmission_type = SdoAbort::ParameterIncompatible;
  p.pdo.cobid_change_requires_invalid = false;
  p.pdo.mapping_requires_invalid = false;
  p.pdo.mapping_entry_requires_sub0_zero = true;
  p.pdo.parameters_preop_only = false;  // the event timer is writable in any state (manual §3.4)
  p.pdo.dummy_mapping = false;
  p.pdo.width_conversion = true;
  p.pdo.mapping_length_mismatch = SdoAbort::ParameterIncompatible;
  p.pdo.sync_producer_refused = SdoAbort::ParameterIncompatible;

  p.store.path.clear();  // nothing survives a power cycle
  return p;
}

void install_communication_rules(canopen::Node& node, const Settings& s) {
  auto& od = node.od();
  auto preop_only = [&node](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    return origin == Origin::Sdo && node.nmt_state() == NmtState::Operational ? SdoAbort::DataDeviceState
                                                                               : SdoAbort::None;
  };
  auto identifier = [](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    return standard_identifier(static_cast<std::uint32_t>(canopen::decode_unsigned(data))) ? SdoAbort::None
                                                                                            : SdoAbort::ParameterIncompatible;
  };
  auto mapping_width = [](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = static_cast<std::uint32_t>(canopen::decode_unsigned(data));
    const auto bits = v & 0xFFu;
    return v == 0 || bits == 0x10 || bits == 0x20 ? SdoAbort::None : SdoAbort::ParameterIncompatible;
  };
  auto hidden_read = [](OdEntry&, Origin origin) { return origin == Origin::Sdo ? SdoAbort::NoObject : SdoAbort::None; };
  auto hidden_write = [](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    return origin == Origin::Sdo ? SdoAbort::NoObject : SdoAbort::None;
  };

  for (std::uint16_t n = 0; n < 4; ++n) {
    for (const std::uint16_t comm : {static_cast<std::uint16_t>(0x1400 + n), static_cast<std::uint16_t>(0x1800 + n)}) {
      add_state_check(od, comm, 1, preop_only);
      add_state_check(od, comm, 1, identifier);
    }
    for (const std::uint16_t map : {static_cast<std::uint16_t>(0x1600 + n), static_cast<std::uint16_t>(0x1A00 + n)}) {
      auto* obj = od.object(map);
      if (!obj) continue;
      for (auto& [sub, entry] : obj->entries) {
        if (!s.expose_mapping_objects) {
          // The card maps only through BODAC: the DS-301 mapping objects do not exist on the bus.
          od.add_check(map, sub, hidden_write, canopen::CheckStage::State);
          od.add_read_hook(map, sub, hidden_read);
          continue;
        }
        add_state_check(od, map, sub, preop_only);
        if (sub != 0) add_state_check(od, map, sub, mapping_width);
      }
    }
  }
  // SYNC and TIME identifiers: stored without function, but only valid 11-bit consumer values.
  for (const std::uint16_t index : {std::uint16_t{0x1005}, std::uint16_t{0x1012}}) {
    add_state_check(od, index, 0, [index](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      if (origin != Origin::Sdo) return SdoAbort::None;
      const auto v = static_cast<std::uint32_t>(canopen::decode_unsigned(data));
      if (!standard_identifier(v)) return SdoAbort::ParameterIncompatible;
      if (index == 0x1005 && (v & kRtrOrProducerBit)) return SdoAbort::ParameterIncompatible;  // no SYNC producer
      return SdoAbort::None;
    });
  }
}

}  // namespace vtvpcd
