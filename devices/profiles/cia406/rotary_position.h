// CiA 406 rotary position arithmetic: physical count → code sequence → scaling (measuring units
// per revolution, total measuring range, which need not be a power of two) → preset offset →
// wrap-around. Pure functions of integers, so a property test can compare them with the formula
// and a power cycle cannot lose a turn: the count is recomputed from the shaft angle.
#pragma once

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

/// Physical count of a shaft at `revolutions` (continuous, clockwise positive):
/// floor(revolutions × resolution), or its value within one turn for a singleturn encoder.
std::int64_t physical_count(double revolutions, const RotaryConfig& c);

/// The scaled count S before wrapping: the code sequence applied to the physical count, then
/// scaled by MUR / resolution (floor). Unbounded for multiturn; in [0, MUR) for singleturn.
Int128 scaled_count(std::int64_t physical, const RotaryConfig& c);

/// Output position X = (S + offset) mod range, in [0, range).
std::uint64_t output_position(Int128 scaled, Int128 offset, const RotaryConfig& c);

/// The offset that makes the current scaled count read `preset`: preset − (S mod range).
Int128 offset_for_preset(std::uint64_t preset, Int128 scaled, const RotaryConfig& c);

}  // namespace cia406
