#include "devices/hlt1100/diagnostics.h"

#include "devices/canopen/emergency.h"
#include "devices/hlt1100/hlt1100_object_dictionary.h"
#include "devices/canopen/entry_ref.h"

namespace hlt1100 {

using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

Diagnostics::Diagnostics(canopen::Node& node, const Settings& settings) : node_(node), settings_(settings) {}

void Diagnostics::bind(cia406::StatusRecorder& recorder) {
  recorder_ = &recorder;
  auto& od = node_.od();
  alarms_entry_ = canopen::EntryRef<std::uint16_t>::optional(od, obj::kAlarms, 0);
  count_entry_ = canopen::EntryRef<std::uint8_t>::optional(od, obj::kErrorField, 0);
  last_entry_entry_ = canopen::EntryRef<std::uint32_t>::optional(od, obj::kErrorField, 1);
  // Reading the error register consumes one entry of the list [M §12.2.1]. The answer carries
  // the register as it was; the EMCY 0x0000 follows the answer.
  od.add_read_hook(obj::kErrorRegister, 0, [this](OdEntry& e, Origin origin) {
    canopen::EntryRef<std::uint8_t>(e).set(error_register());
    if (origin != Origin::Sdo || count_ == 0) return SdoAbort::None;
    --count_;
    if (count_ == 0) communication_latched_ = false;
    emcy(kEmcyNoError);
    return SdoAbort::None;
  });
  od.add_check(obj::kErrorField, 0, [](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
    if (origin != Origin::Sdo) return SdoAbort::None;
    return data[0] == 0 ? SdoAbort::None : SdoAbort::InvalidValue;
  });
  od.add_observer(obj::kErrorField, 0, [this](OdEntry&, Origin origin) {
    if (origin == Origin::Sdo) clear_list(true);
  });
  od.add_read_hook(obj::kErrorField, 0, [this](OdEntry& e, Origin) {
    canopen::EntryRef<std::uint8_t>(e).set(count_);
    return SdoAbort::None;
  });
}

std::uint8_t Diagnostics::error_register() const {
  const std::uint8_t generic = settings_.error_register_generic_bit ? 0x01 : 0x00;
  std::uint8_t er = 0;
  if (alarms_ != 0) er |= 0x20 | generic;
  if (communication_latched_) er |= 0x10 | generic;
  return er;
}

std::uint16_t Diagnostics::emcy_code(std::uint16_t bit) const {
  if (bit == kEepromError) return kEmcyEeprom;
  if (bit == kParameterError) return kEmcyParameter;
  return settings_.position_emcy_code;
}

void Diagnostics::record(std::uint16_t code) {
  if (count_ < 255) ++count_;
  last_entry_ = code;  // one entry, overwritten by each new error [M §8.3]
  publish();
}

void Diagnostics::publish() {
  if (!alarms_entry_) return;  // not bound yet
  alarms_entry_.set(alarms_);
  count_entry_.set(count_);
  last_entry_entry_.set(last_entry_);
  const std::uint8_t er = error_register();
  if (er != published_register_) {
    published_register_ = er;
    node_.emergency().set_extra_register_bits(er);
  }
}

void Diagnostics::set_alarm(std::uint16_t bit, bool active) {
  const bool was = (alarms_ & bit) != 0;
  if (was == active) return;
  alarms_ = static_cast<std::uint16_t>(active ? (alarms_ | bit) : (alarms_ & ~bit));
  if (active) {
    if (recorder_) recorder_->raised_by_fault(cia406::StatusRecorder::Word::Alarms, bit, emcy_code(bit));
    record(emcy_code(bit));
    emcy(emcy_code(bit));
  } else {
    publish();
    emcy(kEmcyNoError);
  }
}

void Diagnostics::communication_error() {
  communication_latched_ = true;
  record(kEmcyCommunication);
  emcy(kEmcyCommunication);
}

void Diagnostics::signal(std::uint16_t code, std::uint8_t register_bits) {
  record(code);
  if (queued_ < queue_.size()) queue_[queued_++] = Pending{code, static_cast<std::uint8_t>(error_register() | register_bits)};
}

void Diagnostics::clear_list(bool send_reset) {
  const bool had = count_ != 0 || communication_latched_;
  count_ = 0;
  last_entry_ = 0;
  communication_latched_ = false;
  publish();
  if (send_reset && had) emcy(kEmcyNoError);
}

void Diagnostics::emcy(std::uint16_t code) {
  // The register as it is when the event happens (a 0x1001 read has already popped its entry).
  if (queued_ < queue_.size()) queue_[queued_++] = Pending{code, error_register()};
}

void Diagnostics::reset_communication() {
  queued_ = 0;
  clear_list(false);
}

void Diagnostics::process() {
  for (std::size_t i = 0; i < queued_; ++i) node_.emergency().send_frame(queue_[i].code, queue_[i].error_register);
  queued_ = 0;
  publish();
}

}  // namespace hlt1100
