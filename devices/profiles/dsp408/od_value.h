// Publishing process values into object-dictionary entries once per control cycle without
// allocating (ObjectDictionary::set and OdEntry::assign build a temporary byte vector), and
// reading integer parameters every cycle without the generic decoder.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "devices/canopen/object_dictionary.h"

namespace dsp408 {

/// Writes an integer into an entry of any integer type (two's complement, truncated to its size).
inline void put(canopen::OdEntry& e, std::int64_t v) { canopen::encode_unsigned(static_cast<std::uint64_t>(v), e.value); }
/// Rounds to the nearest integer, limited to [lo, hi], and writes it.
inline void put_rounded(canopen::OdEntry& e, double v, double lo, double hi) {
  const double c = v < lo ? lo : (v > hi ? hi : v);
  put(e, c == 0.0 ? 0 : static_cast<std::int64_t>(std::llround(c)));  // idle outputs publish 0 every cycle
}

/// An integer parameter entry resolved once, its signedness taken once: the per-cycle read is a
/// size test and one load. The value vector is read at every access (a write or a reset may
/// replace it); an entry of another size or a REAL takes OdEntry::as<std::int64_t>(), whose value
/// get() always equals.
class IntegerParameter {
 public:
  IntegerParameter() = default;
  explicit IntegerParameter(const canopen::OdEntry* e)
      : e_(e),
        signed_(e && canopen::is_signed_integer(e->type)),
        direct_(e && !canopen::is_real(e->type) && std::endian::native == std::endian::little) {}

  explicit operator bool() const { return e_ != nullptr; }
  const canopen::OdEntry* entry() const { return e_; }

  /// The value as OdEntry::as<std::int64_t>() gives it; 0 when unbound.
  std::int64_t get() const {
    if (direct_) [[likely]] {
      if constexpr (std::endian::native == std::endian::little) {
        const canopen::Bytes& v = e_->value;
        switch (v.size()) {
          case 1: return signed_ ? std::int64_t{static_cast<std::int8_t>(v[0])} : std::int64_t{v[0]};
          case 2: {
            std::uint16_t u;
            std::memcpy(&u, v.data(), 2);
            return signed_ ? std::int64_t{static_cast<std::int16_t>(u)} : std::int64_t{u};
          }
          case 4: {
            std::uint32_t u;
            std::memcpy(&u, v.data(), 4);
            return signed_ ? std::int64_t{static_cast<std::int32_t>(u)} : std::int64_t{u};
          }
          default: break;
        }
      }
    }
    return e_ ? e_->as<std::int64_t>() : 0;
  }

 private:
  const canopen::OdEntry* e_ = nullptr;
  bool signed_ = false;
  bool direct_ = false;  // bound, an integer type, little-endian host: the loads above apply
};

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
