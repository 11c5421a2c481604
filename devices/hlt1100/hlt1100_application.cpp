#include "devices/hlt1100/hlt1100_application.h"

#include <cmath>
#include <utility>

#include "devices/canopen/pdo_service.h"
#include "devices/canopen/store_restore.h"
#include "devices/hlt1100/hlt1100_object_dictionary.h"
#include "devices/profiles/cia406/arithmetic.h"

namespace hlt1100 {

using canopen::NmtState;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

namespace {
constexpr std::uint32_t kNmtStartupAuto = 0x08, kNmtStartupManual = 0x0C;
constexpr std::uint16_t kEventTimer = 5;
}  // namespace

namespace {
// The bits the manual documents (6500h bit 3 copies 6000h bit 3; 6505h: "not supported").
constexpr devices::DiagramBit kStatusBits[] = {{3, "code sequence"}};
constexpr devices::DiagramBit kAlarmBits[] = {{0, "position error"}, {12, "EEPROM error"}, {13, "parameter error"}};
}  // namespace

const cia406::StatusBitNames& Application::status_bits() {
  static const cia406::StatusBitNames kNames{kStatusBits, kAlarmBits, {}};
  return kNames;
}

Application::Application(canopen::Node& node, const Settings& settings)
    : node_(node), settings_(settings), diagnostics_(node, settings) {
  (void)signal_.parse(settings.signal);  // validated by parse_settings
  config_.steps = settings.steps();
  config_.manufacturer_offset = settings.manufacturer_offset;
  motion_.configure(settings.speed_window_ms / settings.sample_period_ms == 0 ? 1 : settings.speed_window_ms / settings.sample_period_ms,
                    settings.sample_period_ms * 1e-3);
}

SdoAbort Application::parameter_out_of_range(const OdEntry& entry, std::span<std::uint8_t> data) {
  // The manual lists no abort but an alarm "programmed parameter out of range" (6503h bit 13):
  // the write is confirmed, the parameter keeps its value [REC]; or a plain abort (knob).
  if (settings_.parameter_error_abort) return SdoAbort::InvalidValue;
  std::copy(entry.value.begin(), entry.value.end(), data.begin());
  diagnostics_.set_alarm(kParameterError, true);
  write_ignored_ = true;
  return SdoAbort::None;
}

void Application::bind() {
  auto& od = node_.od();
  diagnostics_.bind(status_recorder_);
  position_ = canopen::EntryRef<std::int32_t>::optional(od, obj::kPosition, 1);
  speed_ = canopen::EntryRef<std::int16_t>::optional(od, obj::kSpeed, 1);
  status_ = canopen::EntryRef<std::uint16_t>::optional(od, obj::kOperatingStatus, 0);

  // 6000h: only the code-sequence bit exists.
  od.add_check(obj::kOperatingParameters, 0, [this](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = canopen::value_as<std::uint16_t>(e.type, data);
    if (v & ~cia406::kLinearCodeSequenceDecreasing) return parameter_out_of_range(e, data);
    diagnostics_.set_alarm(kParameterError, false);
    return SdoAbort::None;
  });
  od.add_observer(obj::kOperatingParameters, 0, [this](OdEntry&, Origin) {
    write_ignored_ = false;
    load_parameters();
    sample(node_.now(), false);
  });

  // 6010h:01 preset: the output becomes the written value now [M §9.3].
  od.add_check(
      obj::kPreset, 1,
      [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
        return origin == Origin::Sdo && !valid_ ? SdoAbort::General : SdoAbort::None;
      },
      canopen::CheckStage::State);
  od.add_check(obj::kPreset, 1, [this](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto preset = canopen::value_as<std::int64_t>(e.type, data);
    if (preset < 0 || preset > config_.steps - 1) return parameter_out_of_range(e, data);
    diagnostics_.set_alarm(kParameterError, false);
    return SdoAbort::None;
  });
  od.add_observer(obj::kPreset, 1, [this](OdEntry& e, Origin origin) {
    if (origin != Origin::Sdo || std::exchange(write_ignored_, false)) return;
    offset_ = cia406::linear_offset_for_preset(e.as<std::int32_t>(), raw_, config_);
    node_.od().set<std::int32_t>(obj::kOffset, 1, static_cast<std::int32_t>(offset_));
    sample(node_.now(), false);
    if (settings_.preset_auto_save && !eeprom_failing_) {
      node_.store().save_entry(obj::kPreset, 1);
      node_.store().save_entry(obj::kOffset, 1);
    }
  });

  // 6200h and 1800h:05 are one variable [M §9.6]; a new value restarts the timer.
  od.add_observer(obj::kCyclicTimer, 0, [this](OdEntry& e, Origin origin) {
    if (origin == Origin::Sdo) sync_cyclic_timer(e.as<std::uint16_t>(), obj::kCyclicTimer);
  });
  od.add_observer(obj::kTpdo1, kEventTimer, [this](OdEntry& e, Origin origin) {
    if (origin == Origin::Sdo) sync_cyclic_timer(e.as<std::uint16_t>(), obj::kTpdo1);
  });

  // 1F80h: 0x08 and 0x0C only [M §8.13].
  od.add_check(obj::kNmtStartup, 0, [](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    const auto v = canopen::value_as<std::uint32_t>(e.type, data);
    return v == kNmtStartupAuto || v == kNmtStartupManual ? SdoAbort::None : SdoAbort::InvalidValue;
  });

  // The offset is a read-only object but is saved with "save all" [M §9.17].
  node_.store().allow_device_stored(obj::kOffset, 1, 1);
  od.add_observer(obj::kStore, 1, [this](OdEntry&, Origin origin) {
    if (origin == Origin::Sdo) node_.store().save_entry(obj::kOffset, 1);
  });
  od.add_check(
      obj::kStore, 1,
      [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (origin == Origin::Sdo && eeprom_failing_ && canopen::decode_unsigned(data) == canopen::StoreRestore::kSaveSignature) {
          diagnostics_.set_alarm(kEepromError, true);
        }
        return SdoAbort::None;
      },
      canopen::CheckStage::State);
  od.add_check(
      0x1011, 1,
      [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (origin == Origin::Sdo && eeprom_failing_ && canopen::decode_unsigned(data) == canopen::StoreRestore::kLoadSignature) {
          diagnostics_.set_alarm(kEepromError, true);
        }
        return SdoAbort::None;
      },
      canopen::CheckStage::State);

  if (settings_.dynamic_mapping) {
    // CiA 301 mapping procedure, Pre-operational only (the COB-ID cannot be invalidated).
    for (std::uint16_t map : {0x1A00, 0x1A01}) {
      for (auto& [sub, entry] : od.object(map)->entries) {
        od.add_check(
            map, sub,
            [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
              return origin == Origin::Sdo && node_.nmt_state() != NmtState::PreOperational ? SdoAbort::DataDeviceState
                                                                                              : SdoAbort::None;
            },
            canopen::CheckStage::State);
      }
    }
  }
}

void Application::sync_cyclic_timer(std::uint16_t ms, std::uint16_t written_index) {
  auto& od = node_.od();
  if (written_index == obj::kCyclicTimer) {
    od.set<std::uint16_t>(obj::kTpdo1, kEventTimer, ms);
  } else {
    od.set<std::uint16_t>(obj::kCyclicTimer, 0, ms);
  }
  node_.pdo().restart_event_timer(1);
}

void Application::load_parameters() {
  auto& od = node_.od();
  const auto op = od.get<std::uint16_t>(obj::kOperatingParameters, 0);
  config_.decreasing = (op & cia406::kLinearCodeSequenceDecreasing) != 0;
  status_.set(static_cast<std::uint16_t>(op & cia406::kLinearCodeSequenceDecreasing));
  offset_ = od.get<std::int32_t>(obj::kOffset, 1);
}

void Application::on_reset_application() {
  if (reset_node_pending_ && settings_.reset_node_factory) {
    node_.od().reset_range(0x2000, 0xFFFF, node_.node_id());  // "profile parameters to default values"
  }
  reset_node_pending_ = false;
  load_parameters();
  diagnostics_.set_alarm(kPositionError, false);  // re-detected (with its EMCY) after boot-up
  diagnostics_.set_alarm(kParameterError, false);
  diagnostics_.set_alarm(kEepromError, false);
  eeprom_check_pending_ = eeprom_failing_;
  valid_ = false;
  next_sample_ = node_.now();
  sample(node_.now(), false);  // the first TPDO (autostart) already carries the position
}

void Application::after_reset_communication() {
  diagnostics_.reset_communication();
  // Reset Communication reloads 1800h:05; 6200h is the same variable.
  node_.od().set<std::uint16_t>(obj::kCyclicTimer, 0, node_.od().get<std::uint16_t>(obj::kTpdo1, kEventTimer));
}

void Application::on_nmt_command(canopen::NmtCommand command) {
  if (command == canopen::NmtCommand::ResetNode) reset_node_pending_ = true;
}

bool Application::autostart() const {
  const auto v = node_.od().get<std::uint32_t>(obj::kNmtStartup, 0);
  const bool bit2 = (v & 0x04) != 0;
  return settings_.nmt_startup_prose ? bit2 : !bit2;
}

void Application::on_nmt_state_changed(NmtState from, NmtState to) {
  // Boot-up done: with autostart the node starts as if it received NMT Start (one-shot TPDO1).
  if (from == NmtState::Initialising && to == NmtState::PreOperational && autostart()) {
    const canopen::Node::CauseScope scope(node_, {devices::TransitionCause::Internal, 0, "autostart (start-up setting)", "autostart"});
    node_.set_nmt_state(NmtState::Operational);
  }
}

bool Application::on_communication_error(canopen::CommError error) {
  if (error == canopen::CommError::BusOffRecovered) {  // digest: a CAN-controller error, 8100h
    can_controller_error();
    return true;
  }
  // Life-guarding timeout: the manual only says "changes to PRE-OPERATIONAL" [M §4.6.1.2].
  if (settings_.life_guard_emcy != 0) diagnostics_.signal(settings_.life_guard_emcy, 0x11);
  if (node_.nmt_state() == NmtState::Operational) node_.set_nmt_state(NmtState::PreOperational);
  return true;
}

void Application::can_controller_error() {
  diagnostics_.communication_error();
  if (node_.nmt_state() == NmtState::Operational) node_.set_nmt_state(NmtState::PreOperational);
}

void Application::set_eeprom_failure(bool failing) {
  eeprom_failing_ = failing;
  node_.store().set_failing(failing);
  if (!failing) diagnostics_.set_alarm(kEepromError, false);
}

void Application::sample(sim::Time now, bool evaluate_alarms) {
  MagnetInputs in = inputs_;
  if (signal_.scripted()) in.position = signal_.value(inputs_.position, sim::seconds(now));
  const Measurement m = measure(in, config_);
  if (m.valid) {
    if (!valid_) motion_.reset(m.micrometres);  // (re)start: no speed spike from the jump
    else if (evaluate_alarms) motion_.push(m.micrometres);
    steps_ = m.steps;
    raw_ = cia406::directed_raw(m.steps, config_);
  }
  valid_ = m.valid;
  if (valid_ || !settings_.hold_last_on_error) {
    const std::int64_t pos = valid_ ? cia406::linear_position(raw_, offset_, config_) : 0;
    position_.set(static_cast<std::int32_t>(pos));
  }
  // Speed in 6005h:02 units (0.01 mm/s each); positive when 6020h rises [REC].
  double speed = 0.0;
  if (valid_) {
    // µm/s → units of 6005h:02 × 0.01 mm/s = 10 µm/s.
    const double um_per_s = motion_.speed() * (config_.decreasing ? -1.0 : 1.0);
    speed = cia406::round_half_away(um_per_s / (10.0 * settings_.speed_step));  // = std::round
  }
  speed_.set(cia406::saturate_i16(speed));
  if (evaluate_alarms) diagnostics_.set_alarm(kPositionError, !valid_);
}

void Application::process(sim::Time now, sim::Duration) {
  if (eeprom_check_pending_) {
    eeprom_check_pending_ = false;
    diagnostics_.set_alarm(kEepromError, true);
  }
  // One sample per sample period, whatever the scheduler's tick.
  const auto period = sim::milliseconds(settings_.sample_period_ms);
  int guard = 0;
  while (next_sample_ <= now && guard++ < 1000) {
    sample(next_sample_, true);
    next_sample_ += period;
  }
  if (next_sample_ <= now) next_sample_ = now + period;
  diagnostics_.process();
  status_recorder_.check();
}

}  // namespace hlt1100
