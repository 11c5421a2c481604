#include "devices/profiles/cia406/rotary_position.h"

#include <bit>
#include <cmath>

namespace cia406 {

std::uint64_t RotaryConfig::effective_units_per_revolution() const {
  return scaling() ? measuring_units_per_revolution : physical_resolution;
}

std::uint64_t RotaryConfig::effective_range() const {
  if (scaling()) return total_measuring_range;
  return multiturn ? static_cast<std::uint64_t>(physical_resolution) * physical_revolutions : physical_resolution;
}

std::int64_t physical_count(double revolutions, const RotaryConfig& c) {
  const auto p = static_cast<std::int64_t>(std::floor(revolutions * c.physical_resolution));
  if (c.multiturn) return p;
  return static_cast<std::int64_t>(floor_mod(p, c.physical_resolution));
}

Int128 scaled_count(std::int64_t physical, const RotaryConfig& c) {
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

Int128 within_turn(Int128 unwrapped_scaled, const RotaryConfig& c) {
  if (c.multiturn) return unwrapped_scaled;
  return floor_mod(unwrapped_scaled, static_cast<Int128>(c.effective_units_per_revolution()));
}

std::uint64_t output_position(Int128 scaled, Int128 offset, const RotaryConfig& c) {
  return static_cast<std::uint64_t>(floor_mod(scaled + offset, static_cast<Int128>(c.effective_range())));
}

Int128 offset_for_preset(std::uint64_t preset, Int128 scaled, const RotaryConfig& c) {
  return static_cast<Int128>(preset) - floor_mod(scaled, static_cast<Int128>(c.effective_range()));
}

}  // namespace cia406
