// The error conditions of a Wandfluh DSP 408 device and their EMCY bookkeeping. Every listed
// error has the reaction "FAULT" (§4.4.1): its rising edge sends one EMCY, sets 0x1001 and
// 0x1003, and faults the channels; it stays latched (no repeated EMCY while it persists) until a
// fault reset finds no error present any more, which sends the "no error" EMCY 0x0000 once.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "devices/canopen/node.h"

namespace wandfluh {

class DeviceErrors {
 public:
  explicit DeviceErrors(canopen::Node& node) : node_(node) {}

  /// Called when an error newly latches (the product faults its channels, outputs off).
  void set_on_error(std::function<void(std::uint16_t code)> f) { on_error_ = std::move(f); }

  /// A lasting condition (fault injection, a port below its threshold): the rising edge latches.
  void set_condition(std::uint16_t code, std::uint8_t register_bits, bool present) {
    // Inline: every condition every tick, nearly always unchanged and in the order of last time.
    Entry* e = next_ < count_ && entries_[next_].code == code ? &entries_[next_++] : find(code, register_bits);
    if (!e) return;
    const bool rising = present && !e->present;
    e->present = present;
    if (rising && !e->latched) raise(*e, true);
  }
  /// An event without a lasting condition (communication fault 0x8100): latches at once.
  /// `notify` false: the caller has already applied the reaction (forced by NMT).
  void latch(std::uint16_t code, std::uint8_t register_bits, bool notify = true);

  bool latched(std::uint16_t code) const;
  bool present(std::uint16_t code) const;
  bool any_present() const;
  bool any_latched() const;

  /// Fault reset (R edge): refused while a condition is still present; otherwise the latched
  /// errors are cleared (EMCY 0x0000 if there were any).
  bool reset();
  /// Application reset: everything forgotten (no EMCY: the node is initialising).
  void clear();

 private:
  struct Entry {
    std::uint16_t code = 0;
    std::uint8_t bits = 0;
    bool present = false;
    bool latched = false;
  };
  Entry* find(std::uint16_t code, std::uint8_t bits);
  const Entry* find(std::uint16_t code) const;
  void raise(Entry& e, bool notify);

  canopen::Node& node_;
  std::array<Entry, 16> entries_{};
  std::size_t count_ = 0;
  std::size_t next_ = 0;  // where the next lookup starts: products check their conditions in a fixed order
  std::function<void(std::uint16_t)> on_error_;
};

}  // namespace wandfluh
