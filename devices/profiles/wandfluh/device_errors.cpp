#include "devices/profiles/wandfluh/device_errors.h"

#include "devices/canopen/emergency.h"

namespace wandfluh {

DeviceErrors::Entry* DeviceErrors::find(std::uint16_t code, std::uint8_t bits) {
  for (std::size_t i = 0; i < count_; ++i) {
    if (entries_[i].code == code) {
      next_ = i + 1;
      return &entries_[i];
    }
  }
  if (count_ == entries_.size()) return nullptr;  // more distinct codes than any manual lists
  entries_[count_] = Entry{code, bits, false, false};
  next_ = count_ + 1;
  return &entries_[count_++];
}

const DeviceErrors::Entry* DeviceErrors::find(std::uint16_t code) const {
  for (std::size_t i = 0; i < count_; ++i)
    if (entries_[i].code == code) return &entries_[i];
  return nullptr;
}

void DeviceErrors::raise(Entry& e, bool notify) {
  e.latched = true;
  node_.emergency().raise(e.code, e.bits);
  if (notify && on_error_) on_error_(e.code);
}

void DeviceErrors::latch(std::uint16_t code, std::uint8_t register_bits, bool notify) {
  Entry* e = find(code, register_bits);
  if (e && !e->latched) raise(*e, notify);
}

bool DeviceErrors::latched(std::uint16_t code) const {
  const Entry* e = find(code);
  return e && e->latched;
}

bool DeviceErrors::present(std::uint16_t code) const {
  const Entry* e = find(code);
  return e && e->present;
}

bool DeviceErrors::any_present() const {
  for (std::size_t i = 0; i < count_; ++i)
    if (entries_[i].present) return true;
  return false;
}

bool DeviceErrors::any_latched() const {
  for (std::size_t i = 0; i < count_; ++i)
    if (entries_[i].latched) return true;
  return false;
}

bool DeviceErrors::reset() {
  if (any_present()) return false;
  for (std::size_t i = 0; i < count_; ++i) entries_[i].latched = false;
  node_.emergency().clear_all();  // one "no error" EMCY if anything was active
  return true;
}

void DeviceErrors::clear() {
  // Conditions are detected afresh after the reset (a still-open solenoid raises again).
  for (std::size_t i = 0; i < count_; ++i) entries_[i].latched = entries_[i].present = false;
  node_.emergency().clear_all();
}

}  // namespace wandfluh
