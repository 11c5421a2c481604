// Publishing process values into object-dictionary entries once per control cycle without
// allocating (ObjectDictionary::set and OdEntry::assign build a temporary byte vector), and
// reading integer parameters every cycle without the generic decoder (devices::IntegerEntry).
#pragma once

#include <cmath>
#include <cstdint>

#include "devices/canopen/object_dictionary.h"
#include "devices/entry_value.h"

namespace dsp408 {

/// Writes an integer into an entry of any integer type (two's complement, truncated to its size).
inline void put(canopen::OdEntry& e, std::int64_t v) { canopen::encode_unsigned(static_cast<std::uint64_t>(v), e.value); }
/// Rounds to the nearest integer, limited to [lo, hi], and writes it.
inline void put_rounded(canopen::OdEntry& e, double v, double lo, double hi) {
  const double c = v < lo ? lo : (v > hi ? hi : v);
  put(e, c == 0.0 ? 0 : static_cast<std::int64_t>(std::llround(c)));  // idle outputs publish 0 every cycle
}

/// put_rounded() for an output published every cycle whose value moves slowly (a temperature):
/// the rounding is skipped while the value stays strictly inside the half-open step of the
/// integer published last and the entry still holds it.
class RoundedOutput {
 public:
  RoundedOutput() = default;
  RoundedOutput(canopen::OdEntry* e, double lo, double hi) : e_(e), lo_(lo), hi_(hi) {}

  void put(double v) {
    // llround(c) == k exactly for every c in the open interval (k − ½, k + ½) (and the limits
    // are integers, so the clamp cannot move a value out of it).
    if (written_ && v > k_ - 0.5 && v < k_ + 0.5 && v >= lo_ && v <= hi_ && canopen::decode_unsigned(e_->value) == bits_) return;
    put_rounded(*e_, v, lo_, hi_);
    const double c = v < lo_ ? lo_ : (v > hi_ ? hi_ : v);
    k_ = c == 0.0 ? 0.0 : static_cast<double>(std::llround(c));
    bits_ = canopen::decode_unsigned(e_->value);
    written_ = true;
  }

 private:
  canopen::OdEntry* e_ = nullptr;
  double lo_ = 0, hi_ = 0;
  double k_ = 0;                 // the integer written last
  std::uint64_t bits_ = 0;       // and its bytes in the entry
  bool written_ = false;
};

}  // namespace dsp408
