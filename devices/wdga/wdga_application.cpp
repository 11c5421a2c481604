#include "devices/wdga/wdga_application.h"

#include <set>
#include <utility>

#include "devices/canopen/lss_slave.h"
#include "devices/canopen/pdo_service.h"
#include "devices/canopen/store_restore.h"
#include "devices/canopen/entry_ref.h"
#include "devices/wdga/wdga_object_dictionary.h"

namespace wdga {

using canopen::CheckStage;
using canopen::NmtState;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;
using cia406::Int128;

namespace {
constexpr sim::Duration kCycle = sim::milliseconds(1);
constexpr std::uint16_t kEmcyEeprom = 0x5000, kEmcyOverrun = 0x8110, kEmcyPassive = 0x8120, kEmcyBusOffRecovered = 0x8140;
constexpr std::uint16_t kEmcyCommunication = 0x8100, kEmcyHeartbeat = 0x8130;
/// EMCY info1 of 8100h/8120h [M Tab. 7.9]: low nibble CAN state, high nibble last error (4 CRC).
constexpr std::uint8_t kInfoBusWarning = 0x46, kInfoErrorActive = 0x01;
/// Hidden non-volatile cell of the full 64-bit preset offset (6509h shows only 32 bits): stored
/// with "save all"/"save application", erased by the matching restore.
constexpr std::uint16_t kOffsetCellIndex = 0x6509;
constexpr std::uint8_t kOffsetCellSub = 0xFF;

bool restricted_cob_id(std::uint32_t id) {
  // CiA 301 §7.3.5: identifiers reserved for NMT, SYNC/EMCY ranges of others, SDO, NMT error
  // control and LSS.
  return id == 0x000 || (id >= 0x001 && id <= 0x07F) || (id >= 0x101 && id <= 0x180) || (id >= 0x581 && id <= 0x5FF) ||
         (id >= 0x601 && id <= 0x67F) || (id >= 0x6E0 && id <= 0x6FF) || id >= 0x701;
}
}  // namespace

namespace {
// The bits the manual documents (Tab. 7.11, 7.12, 8.61).
constexpr devices::DiagramBit kStatusBits[] = {{0, "code sequence"}, {2, "scaling function"}};
constexpr devices::DiagramBit kAlarmBits[] = {{0, "position error"}};
constexpr devices::DiagramBit kWarningBits[] = {
    {0, "frequency limit exceeded"}, {12, "over-temperature"}, {13, "under-temperature"}, {14, "temperature read failed"}};
}  // namespace

const cia406::StatusBitNames& Application::status_bits() {
  static const cia406::StatusBitNames kNames{kStatusBits, kAlarmBits, kWarningBits};
  return kNames;
}

Application::Application(canopen::Node& node, const Settings& settings)
    : node_(node),
      settings_(settings),
      diagnostics_(node, settings),
      measurement_(node.od(), settings),
      temperature_(node.od(), diagnostics_, settings.temperature_period_s) {}

void Application::bind() {
  diagnostics_.bind(status_recorder_);
  temperature_.bind();
  bind_node_objects();
  bind_measurement_objects();
  bind_pdo_rules();
  bind_storage();
  bind_configuration_stamp();
}

// ---- 2100h/2101h, 1F80h, 1029h ----------------------------------------------------------------

void Application::bind_node_objects() {
  auto& od = node_.od();
  auto preop_only = [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    return origin == Origin::Sdo && node_.nmt_state() != NmtState::PreOperational ? SdoAbort::DataDeviceState
                                                                                  : SdoAbort::None;
  };
  // Node-ID and bit rate are the LSS cells: pending value read back, saved on write, active
  // after the next reset [M §4.2, §8.3.3, §8.3.4].
  for (std::uint16_t index : {obj::kBitRate, obj::kNodeId}) {
    od.add_check(index, 0, preop_only, CheckStage::State);
    od.add_read_hook(index, 0, [this, index](OdEntry& e, Origin) {
      auto& lss = *node_.lss();
      canopen::EntryRef<std::uint8_t>(e).set(index == obj::kNodeId ? lss.pending_node_id() : lss.pending_bit_rate());
      return SdoAbort::None;
    });
    od.add_check(index, 0, [this, index](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      if (origin != Origin::Sdo) return SdoAbort::None;
      auto& lss = *node_.lss();
      const std::uint8_t v = data[0];
      const std::uint8_t error = index == obj::kNodeId ? lss.configure_node_id(v) : lss.configure_bit_rate(v);
      if (error != 0) return SdoAbort::InvalidValue;
      if (!lss.store_configuration()) {
        eeprom_error(0x08);
        return SdoAbort::HardwareError;
      }
      return SdoAbort::None;
    });
  }
  od.add_check(obj::kNmtStartup, 0, [](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = canopen::value_as<std::uint32_t>(e.type, data);
    return v == 0x00 || v == 0x02 || v == 0x08 ? SdoAbort::None : SdoAbort::InvalidValue;
  });
  for (std::uint8_t sub : {1, 2}) {
    od.add_check(obj::kErrorBehaviour, sub, [](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
      return origin == Origin::Sdo && data[0] > 2 ? SdoAbort::InvalidValue : SdoAbort::None;
    });
  }
}

// ---- measurement objects ------------------------------------------------------------------

void Application::bind_measurement_objects() {
  auto& od = node_.od();
  od.add_check(obj::kOperatingParameters, 0, [](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = canopen::value_as<std::uint16_t>(e.type, data);
    return v == 0x0000 || v == 0x0001 || v == 0x0004 || v == 0x0005 ? SdoAbort::None : SdoAbort::InvalidValue;
  });
  od.add_check(obj::kTotalRange, 0, [this](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = canopen::value_as<std::uint32_t>(e.type, data);
    if (v == 0) return settings_.is_32bit_variant ? SdoAbort::None : SdoAbort::InvalidValue;
    const std::uint32_t max = settings_.multiturn ? settings_.total_range_max
                                                  : node_.od().get<std::uint32_t>(obj::kUnitsPerRevolution);
    return v > max ? SdoAbort::ValueTooHigh : SdoAbort::None;
  });
  for (std::uint16_t index : {obj::kOperatingParameters, obj::kUnitsPerRevolution, obj::kTotalRange}) {
    od.add_observer(index, 0, [this](OdEntry&, Origin origin) {
      if (origin == Origin::Sdo) measurement_.parameters_changed(node_.now());
    });
  }
  // Preset: the present position reads the written value [M §8.7].
  auto preset_in_range = [this](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    return canopen::value_as<std::uint64_t>(e.type, data) < measurement_.range() ? SdoAbort::None : SdoAbort::InvalidValue;
  };
  for (std::uint16_t index : {obj::kPreset, obj::kPresetHigh}) {
    od.add_check(index, 0, preset_in_range);
    od.add_observer(index, 0, [this](OdEntry& e, Origin origin) {
      if (origin == Origin::Sdo) measurement_.preset(e.as<std::uint64_t>());
    });
  }
  od.add_observer(obj::kIntegration, 2, [this](OdEntry&, Origin) { measurement_.window_changed(); });
  for (auto [index, sub] : {std::pair<std::uint16_t, std::uint8_t>{obj::kIntegration, 1}, {obj::kSpeedScaling, 1},
                            {obj::kSpeedScaling, 2}, {obj::kFrequencyLimit, 0}}) {
    od.add_observer(index, sub, [this](OdEntry&, Origin) { measurement_.load_parameters(); });
  }
  od.add_observer(obj::kCyclicTimer, 0, [this](OdEntry&, Origin origin) {
    if (origin != Origin::Sdo) return;
    if (settings_.cyclic_timer_alias) {
      node_.od().set<std::uint16_t>(0x1800, 5, node_.od().get<std::uint16_t>(obj::kCyclicTimer));
      node_.pdo().restart_event_timer(1);
    }
    apply_cyclic_timer();
  });
  if (settings_.cyclic_timer_alias) {
    od.add_observer(0x1800, 5, [this](OdEntry& e, Origin origin) {
      if (origin == Origin::Sdo) node_.od().set<std::uint16_t>(obj::kCyclicTimer, 0, e.as<std::uint16_t>());
    });
  }
}

void Application::apply_cyclic_timer() {
  // 6200h paces change-driven TPDO1 (default 1 ms, 0 treated as 1) [R, A-15]; as an alias of
  // 1800h:05 it is the event timer instead and paces nothing.
  const auto ms = node_.od().get<std::uint16_t>(obj::kCyclicTimer);
  node_.pdo().set_min_spacing(1, settings_.cyclic_timer_alias ? sim::Duration{0} : sim::milliseconds(ms == 0 ? 1 : ms));
}

// ---- PDO parameter rules ------------------------------------------------------------------

void Application::bind_pdo_rules() {
  auto& od = node_.od();
  auto preop_only = [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    return origin == Origin::Sdo && node_.nmt_state() == NmtState::Operational ? SdoAbort::DataDeviceState
                                                                               : SdoAbort::None;
  };
  for (std::uint16_t n = 0; n < 4; ++n) {
    const auto comm = static_cast<std::uint16_t>(0x1800 + n), map = static_cast<std::uint16_t>(0x1A00 + n);
    // Transmission type and event timer only in Pre-operational [M §8.5.1]; mapping likewise.
    od.add_check(comm, 2, preop_only, CheckStage::State);
    od.add_check(comm, 5, preop_only, CheckStage::State);
    for (auto& [sub, e] : od.object(map)->entries) od.add_check(map, sub, preop_only, CheckStage::State);
    if (settings_.strict_cobid) {
      od.add_check(comm, 1, [](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        const auto v = static_cast<std::uint32_t>(canopen::decode_unsigned(data));
        if (origin != Origin::Sdo || (v & 0xA0000000u)) return SdoAbort::None;  // invalid or 29-bit
        return restricted_cob_id(v & 0x7FF) ? SdoAbort::InvalidValue : SdoAbort::None;
      });
    }
  }
}

// ---- storage ------------------------------------------------------------------------------

void Application::stage_offset() {
  auto& nv = node_.store().memory();
  canopen::Bytes bytes(8);
  canopen::encode_unsigned(static_cast<std::uint64_t>(static_cast<std::int64_t>(measurement_.offset())), bytes);
  nv.put(kOffsetCellIndex, kOffsetCellSub, canopen::ParameterStore::Value{false, bytes});
}

void Application::bind_storage() {
  node_.store().allow_device_stored(kOffsetCellIndex, kOffsetCellSub, kOffsetCellSub);  // stage_offset()
  auto& od = node_.od();
  for (std::uint8_t sub = 1; sub <= 4; ++sub) {
    // A failing EEPROM: the abort comes from the stack, the EMCY from here.
    od.add_check(
        obj::kStore, sub,
        [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
          if (origin == Origin::Sdo && eeprom_failing_ &&
              canopen::decode_unsigned(data) == canopen::StoreRestore::kSaveSignature) {
            eeprom_error(0x08);
          }
          return SdoAbort::None;
        },
        CheckStage::State);
    od.add_check(
        obj::kRestore, sub,
        [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
          if (origin == Origin::Sdo && eeprom_failing_ &&
              canopen::decode_unsigned(data) == canopen::StoreRestore::kLoadSignature) {
            eeprom_error(0x08);
          }
          return SdoAbort::None;
        },
        CheckStage::State);
  }
  for (std::uint8_t sub : {1, 3}) {
    // The offset cell goes into the memory before the stack writes the file: one write.
    od.add_check(
        obj::kStore, sub,
        [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
          if (origin == Origin::Sdo && !eeprom_failing_ &&
              canopen::decode_unsigned(data) == canopen::StoreRestore::kSaveSignature) {
            stage_offset();
          }
          return SdoAbort::None;
        },
        CheckStage::State);
  }
  if (settings_.restore_at_once) {
    for (std::uint8_t sub = 1; sub <= 4; ++sub) {
      od.add_observer(obj::kRestore, sub, [this, sub](OdEntry&, Origin origin) {
        if (origin == Origin::Sdo) apply_restored_defaults(sub);  // only after a successful "load"
      });
    }
  }
  // Customer data: saved on write, untouched by restore [M §7.12].
  for (std::uint8_t sub = 1; sub <= 8; ++sub) {
    od.add_check(
        obj::kCustomerData, sub,
        [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
          return origin == Origin::Sdo && eeprom_failing_ ? SdoAbort::HardwareError : SdoAbort::None;
        },
        CheckStage::State);
    od.add_observer(obj::kCustomerData, sub, [this, sub](OdEntry&, Origin origin) {
      if (origin == Origin::Sdo) node_.store().save_entry(obj::kCustomerData, sub);
    });
  }
}

void Application::apply_restored_defaults(std::uint8_t sub) {
  // The values the stack would load at the next reset: the defaults of every storable entry of
  // the group (the stack erased the stored ones). Written with Origin::Restore, so the services
  // take them up at once (heartbeat, PDOs, ...) while the SDO-only rules stay out of the way.
  // 2100h/2101h are not persistent entries (LSS cells) and 2120h is in no group [M §8.12.2].
  auto& od = node_.od();
  const std::uint8_t id = node_.node_id();
  for (const auto& group : node_.policy().store.groups) {
    if (group.sub != sub) continue;
    for (const auto& [first, last] : group.ranges) {
      for (auto it = od.objects().lower_bound(first); it != od.objects().end() && it->first <= last; ++it) {
        if (it->first == obj::kStore || it->first == obj::kRestore || it->first == 0x1003) continue;
        for (const auto& [entry_sub, entry] : it->second.entries) {
          OdEntry* e = od.entry(it->first, entry_sub);
          if (!e || !e->persistent || !e->writable()) continue;
          const canopen::Bytes value = e->default_for_node(id);
          if (e->value == value) continue;
          if (od.write(*e, value, Origin::Restore) != SdoAbort::None) e->reset_to_default(id);
        }
      }
    }
  }
  if (sub == 1 || sub == 2) node_.rebuild_dispatch();
  if (sub == 1 || sub == 3) {
    // Scaling back to the defaults; the erased offset cell means offset 0, as after a reset.
    measurement_.parameters_changed(node_.now());
    apply_cyclic_timer();
  }
}

// 1020h: any change of the configuration clears the stamp [M §7.14].
void Application::bind_configuration_stamp() {
  auto& od = node_.od();
  const std::set<std::pair<std::uint16_t, std::uint8_t>> not_configuration = {
      {obj::kStore, 1}, {obj::kStore, 2}, {obj::kStore, 3}, {obj::kStore, 4},
      {0x1003, 0},      {obj::kWarningHistory, 0}};
  for (auto& [index, object] : od.objects()) {
    if (index == obj::kVerifyConfiguration) continue;
    for (auto& [sub, e] : object.entries) {
      if (!e.writable() || not_configuration.count({index, sub})) continue;
      od.add_observer(index, sub, [this](OdEntry&, Origin origin) {
        if (origin != Origin::Sdo) return;
        node_.od().set<std::uint32_t>(obj::kVerifyConfiguration, 1, 0u);
        node_.od().set<std::uint32_t>(obj::kVerifyConfiguration, 2, 0u);
      });
    }
  }
}

// ---- faults -------------------------------------------------------------------------------

void Application::eeprom_error(std::uint8_t info2) {
  diagnostics_.set_status(kStatusEeprom, true);
  if (node_.emergency().active(kEmcyEeprom)) return;
  diagnostics_.raise(kEmcyEeprom, kErGeneric, {0, info2, 0, 0, 0});
  diagnostics_.apply_device_error_behaviour();
}

void Application::set_eeprom_failure(bool failing) {
  eeprom_failing_ = failing;
  node_.store().set_failing(failing);
  if (!failing) {
    diagnostics_.set_status(kStatusEeprom, false);
    diagnostics_.clear(kEmcyEeprom);
  }
}

void Application::set_position_error(bool active) {
  if (active == position_error_) return;
  position_error_ = active;
  diagnostics_.set_alarms(active ? 0x0001 : 0x0000, settings_.position_error_emcy);
  diagnostics_.set_status(settings_.multiturn ? kStatusMultiturnError : kStatusSingleturnError, active);
  // No EMCY code is documented for the position error: register bit 0 only, or a knob.
  if (settings_.position_error_emcy != 0) {
    if (active) {
      diagnostics_.raise(settings_.position_error_emcy, kErGeneric);
    } else {
      diagnostics_.clear(settings_.position_error_emcy);
    }
  } else {
    node_.emergency().set_extra_register_bits(active ? kErGeneric : 0);
  }
  if (active) diagnostics_.apply_device_error_behaviour();
}

void Application::set_error_passive(bool active) {
  if (active) {
    diagnostics_.raise(kEmcyPassive, kErCommunication, {0x47, 0, 0, 0, 0});  // CRC errors, bus passive
  } else {
    diagnostics_.clear(kEmcyPassive);
  }
}

void Application::set_bus_warning(bool active) {
  if (active == bus_warning_) return;
  bus_warning_ = active;
  if (!settings_.bus_warning_emcy) return;  // a bus warning is then no error on the bus
  if (active) {
    diagnostics_.raise(kEmcyCommunication, kErCommunication, {kInfoBusWarning, 0, 0, 0, 0});
    return;
  }
  // Back to error-active (info1 low nibble 1) unless the controller is still error passive:
  // 8100h with the register as it is without the warning, then the usual error reset.
  if (!node_.emergency().active(kEmcyPassive)) {
    std::uint8_t reg = node_.emergency().error_register();
    if (!node_.emergency().active(kEmcyHeartbeat)) reg = static_cast<std::uint8_t>(reg & ~kErCommunication);
    node_.emergency().send_frame(kEmcyCommunication, reg, {kInfoErrorActive, 0, 0, 0, 0});
  }
  diagnostics_.clear(kEmcyCommunication);
}

void Application::receive_overrun() { diagnostics_.signal(kEmcyOverrun, kErCommunication, {0x01, 0, 0, 0, 0}); }

void Application::go_bus_off() {
  // Silent on the bus; only a power cycle helps unless 2103h sets an automatic reset [M §7.11].
  bus_off_ = true;
  node_.set_bus_off(true);
  const auto seconds = node_.od().get<std::uint8_t>(obj::kBusOffReset);
  bus_off_recovers_ = seconds != 0;
  bus_off_until_ = node_.now() + sim::milliseconds(static_cast<std::int64_t>(seconds) * 1000);
}

// ---- life cycle -----------------------------------------------------------------------------

void Application::on_reset_application() {
  const auto* cell = node_.store().memory().find(kOffsetCellIndex, kOffsetCellSub);
  const Int128 offset = cell && cell->bytes.size() == 8 ? static_cast<std::int64_t>(canopen::decode_unsigned(cell->bytes)) : 0;
  measurement_.restart(node_.now(), offset);
  temperature_.restart(node_.now());
  next_cycle_ = node_.now() + kCycle;
  eeprom_boot_check_ = eeprom_failing_;  // the EEPROM is read at every initialisation
}

void Application::on_reset_communication() {
  // A bit rate configured by 2100h or LSS applies at the next reset [M §8.3.3].
  node_.lss()->activate_pending_bit_rate();
}

void Application::after_reset_communication() { apply_cyclic_timer(); }

void Application::on_nmt_state_changed(NmtState from, NmtState to) {
  if (from != NmtState::Initialising || to != NmtState::PreOperational) return;
  if (eeprom_boot_check_) {
    eeprom_boot_check_ = false;
    eeprom_error(0x01);  // "Init EEPROM-Fehler", right after the boot-up frame
  }
  // 1F80h [M §7.10]: 08h Operational by itself; 02h also "start all nodes".
  const auto startup = node_.od().get<std::uint32_t>(obj::kNmtStartup);
  if (startup == 0x02) node_.send(sim::CanFrame::data_frame(0x000, {0x01, 0x00}));
  if (startup == 0x02 || startup == 0x08) {
    const canopen::Node::CauseScope scope(node_, {devices::TransitionCause::Internal, startup, "NMT start-up 1F80h", "1F80h"});
    node_.set_nmt_state(NmtState::Operational);
  }
}

bool Application::on_communication_error(canopen::CommError error) {
  if (error == canopen::CommError::BusOffRecovered) {  // a bus-off the scenario made on the wire
    bus_off_recovered();
    return true;
  }
  diagnostics_.record_error(node_.policy().error_control.heartbeat_consumer_emcy);
  return false;  // the stack sends 8130h and applies 1029h:01
}

void Application::bus_off_recovered() {
  diagnostics_.signal(kEmcyBusOffRecovered, kErCommunication, {0x01, 0, 0, 0, 0});
  const canopen::Node::CauseScope scope(node_, {devices::TransitionCause::BusOff, 0, "recovered", "1029h:01"});
  diagnostics_.apply_communication_error_behaviour();
}

void Application::process(sim::Time now, sim::Duration) {
  if (bus_off_ && bus_off_recovers_ && now >= bus_off_until_) {
    bus_off_ = false;
    node_.set_bus_off(false);
    bus_off_recovered();
  }
  // The 1 ms internal cycle, whatever the scheduler's tick (several cycles per long tick).
  int guard = 0;
  while (next_cycle_ <= now && guard++ < 1000) {
    measurement_.cycle(next_cycle_);
    next_cycle_ += kCycle;
  }
  if (next_cycle_ <= now) next_cycle_ = now + kCycle;
  const std::uint16_t warnings = measurement_.frequency_exceeded() ? (diagnostics_.warnings() | kWarnFrequency)
                                                                   : (diagnostics_.warnings() & ~kWarnFrequency);
  diagnostics_.set_warnings(warnings);
  temperature_.process(now);
  status_recorder_.check();
}

}  // namespace wdga
