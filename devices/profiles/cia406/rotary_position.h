// CiA 406 rotary position arithmetic: physical count → code sequence → scaling (measuring units
// per revolution, total measuring range, which need not be a power of two) → preset offset →
// wrap-around. Pure functions of integers, so a property test can compare them with the formula
// and a power cycle cannot lose a turn: the count is recomputed from the shaft angle.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "devices/profiles/cia406/arithmetic.h"

namespace cia406 {

/// Operating parameters (6000h) bits of a rotary encoder.
inline constexpr std::uint16_t kCodeSequenceCounterClockwise = 0x0001;
inline constexpr std::uint16_t kScalingFunction = 0x0004;

struct RotaryConfig {
  std::uint32_t physical_resolution = 16384;      ///< steps per revolution (6501h)
  bool multiturn = true;
  std::uint64_t physical_revolutions = 1ull << 39;  ///< multiturn counter range (6510h)
  std::uint16_t operating_parameters = kScalingFunction;  ///< 6000h
  std::uint32_t measuring_units_per_revolution = 16384;   ///< 6001h (used with scaling on)
  /// 6002h as it acts: the caller maps a written 0 to 2^32 where that is legal.
  std::uint64_t total_measuring_range = 1ull << 30;

  bool counter_clockwise() const { return operating_parameters & kCodeSequenceCounterClockwise; }
  bool scaling() const { return operating_parameters & kScalingFunction; }
  /// Steps per revolution of the output (MUR with scaling, the physical resolution without).
  std::uint64_t effective_units_per_revolution() const;
  /// The range the output wraps at: TMR with scaling; without scaling the physical range
  /// (resolution for singleturn, resolution × revolutions for multiturn).
  std::uint64_t effective_range() const;
};

// Inline: an encoder runs these in every measurement cycle.

/// Physical count of a shaft at `revolutions` (continuous, clockwise positive):
/// floor(revolutions × resolution), or its value within one turn for a singleturn encoder.
inline std::int64_t physical_count(double revolutions, const RotaryConfig& c) {
  const auto p = static_cast<std::int64_t>(std::floor(revolutions * c.physical_resolution));
  if (c.multiturn) return p;
  return static_cast<std::int64_t>(floor_mod(p, c.physical_resolution));
}

/// The scaled count S before wrapping: the code sequence applied to the physical count, then
/// scaled by MUR / resolution (floor). Unbounded for multiturn; in [0, MUR) for singleturn.
inline Int128 scaled_count(std::int64_t physical, const RotaryConfig& c) {
  const Int128 res = c.physical_resolution;
  Int128 directed = c.counter_clockwise() ? -static_cast<Int128>(physical) : static_cast<Int128>(physical);
  if (!c.multiturn) directed = floor_mod(directed, res);  // a singleturn count restarts every turn
  if (!c.scaling()) return directed;
  const Int128 product = directed * static_cast<Int128>(c.measuring_units_per_revolution);
  // A power-of-two resolution (16384 on the WDGA): the floor division is an arithmetic shift.
  if (c.physical_resolution != 0 && (c.physical_resolution & (c.physical_resolution - 1)) == 0) {
    return product >> std::countr_zero(c.physical_resolution);
  }
  return floor_div(product, res);
}

/// The count of the output turn: a multiturn count as it is, a singleturn count reduced to one
/// revolution (used when the scaled count was computed unwrapped, e.g. for filtering).
inline Int128 within_turn(Int128 unwrapped_scaled, const RotaryConfig& c) {
  if (c.multiturn) return unwrapped_scaled;
  return floor_mod(unwrapped_scaled, static_cast<Int128>(c.effective_units_per_revolution()));
}

/// Output position X = (S + offset) mod range, in [0, range).
std::uint64_t output_position(Int128 scaled, Int128 offset, const RotaryConfig& c);

/// The offset that makes the current scaled count read `preset`: preset − (S mod range).
Int128 offset_for_preset(std::uint64_t preset, Int128 scaled, const RotaryConfig& c);

}  // namespace cia406
