#include "devices/wdga/diagnostics.h"

#include "devices/canopen/entry_ref.h"
#include "devices/wdga/wdga_object_dictionary.h"

namespace wdga {

using canopen::NmtState;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

Diagnostics::Diagnostics(canopen::Node& node, const Settings& settings) : node_(node), settings_(settings) {}

void Diagnostics::bind(cia406::StatusRecorder& recorder) {
  recorder_ = &recorder;
  auto& od = node_.od();
  // 2504h:00 is rw: writing 0 clears the warning history [R].
  od.add_check(obj::kWarningHistory, 0, [](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    return data[0] == 0 ? SdoAbort::None : SdoAbort::InvalidValue;
  });
  od.add_observer(obj::kWarningHistory, 0, [this](OdEntry&, Origin origin) {
    if (origin != Origin::Sdo) return;
    warning_count_ = 0;
    warning_history_.fill(0);
    for (std::uint8_t i = 1; i <= 5; ++i) node_.od().set<std::uint16_t>(obj::kWarningHistory, i, 0);
  });
  // The histories live in the device (EEPROM), not in the dictionary's reset defaults.
  for (std::uint16_t index : {obj::kErrorHistory, obj::kAlarmHistory, obj::kWarningHistory}) {
    for (std::uint8_t sub = 0; sub <= 5; ++sub) {
      od.add_read_hook(index, sub, [this, index, sub](OdEntry& e, Origin) {
        if (index == obj::kErrorHistory) {
          canopen::EntryRef<std::uint32_t>(e).set(sub == 0 ? error_count_ : errors_[sub - 1]);
        } else if (index == obj::kAlarmHistory) {
          canopen::EntryRef<std::uint32_t>(e).set(sub == 0 ? alarm_count_ : alarm_history_[sub - 1]);
        } else {
          canopen::EntryRef<std::uint32_t>(e).set(sub == 0 ? warning_count_ : warning_history_[sub - 1]);
        }
        return SdoAbort::None;
      });
    }
  }
}

template <typename T>
void Diagnostics::push(std::array<T, 5>& history, std::uint8_t& count, T value, std::uint16_t) {
  for (std::size_t i = history.size() - 1; i > 0; --i) history[i] = history[i - 1];  // newest first
  history[0] = value;
  if (count < history.size()) ++count;
}

void Diagnostics::record_error(std::uint16_t code, const canopen::Emergency::Info& info) {
  const std::uint32_t entry = (static_cast<std::uint32_t>(info[0]) | static_cast<std::uint32_t>(info[1]) << 8) << 16 | code;
  push(errors_, error_count_, entry, obj::kErrorHistory);
}

void Diagnostics::raise(std::uint16_t code, std::uint8_t register_bits, canopen::Emergency::Info info) {
  if (node_.emergency().active(code)) return;
  record_error(code, info);
  node_.emergency().raise(code, register_bits, info);
}

void Diagnostics::clear(std::uint16_t code) { node_.emergency().clear(code); }

void Diagnostics::signal(std::uint16_t code, std::uint8_t register_bits, canopen::Emergency::Info info) {
  record_error(code, info);
  node_.emergency().signal(code, register_bits, info);
}

void Diagnostics::set_alarms(std::uint16_t alarms, std::uint16_t emcy_code) {
  if (alarms == alarms_) return;
  if (recorder_) recorder_->raised_by_fault(cia406::StatusRecorder::Word::Alarms, alarms & ~alarms_, emcy_code);
  if (alarms & ~alarms_) push(alarm_history_, alarm_count_, alarms, obj::kAlarmHistory);
  alarms_ = alarms;
  node_.od().set<std::uint16_t>(obj::kAlarms, 0, alarms);
}

void Diagnostics::set_warnings(std::uint16_t warnings) {
  if (warnings == warnings_) return;
  if (warnings & ~warnings_) push(warning_history_, warning_count_, warnings, obj::kWarningHistory);
  warnings_ = warnings;
  node_.od().set<std::uint16_t>(obj::kWarnings, 0, warnings);
}

void Diagnostics::set_warnings(std::uint16_t warnings, std::uint16_t emcy_code) {
  if (recorder_) recorder_->raised_by_fault(cia406::StatusRecorder::Word::Warnings, warnings & ~warnings_, emcy_code);
  set_warnings(warnings);
}

void Diagnostics::set_status(std::uint32_t bits, bool on) {
  status_ = on ? (status_ | bits) : (status_ & ~bits);
  node_.od().set<std::uint32_t>(obj::kManufacturerStatus, 0, status_);
}

void Diagnostics::apply(std::uint8_t sub) {
  switch (node_.od().get<std::uint8_t>(obj::kErrorBehaviour, sub)) {
    case 0:
      if (node_.nmt_state() == NmtState::Operational) node_.set_nmt_state(NmtState::PreOperational);
      break;
    case 2: node_.set_nmt_state(NmtState::Stopped); break;
    default: break;  // 1: the state does not change
  }
}

void Diagnostics::apply_device_error_behaviour() {
  const canopen::Node::CauseScope scope(node_, {devices::TransitionCause::DeviceFault, 0, "position error", "1029h:02"});
  apply(2);
}
void Diagnostics::apply_communication_error_behaviour() { apply(1); }

}  // namespace wdga
