#include "devices/profiles/cia406/rotary_position.h"

namespace cia406 {

std::uint64_t RotaryConfig::effective_units_per_revolution() const {
  return scaling() ? measuring_units_per_revolution : physical_resolution;
}

std::uint64_t RotaryConfig::effective_range() const {
  if (scaling()) return total_measuring_range;
  return multiturn ? static_cast<std::uint64_t>(physical_resolution) * physical_revolutions : physical_resolution;
}

std::uint64_t output_position(Int128 scaled, Int128 offset, const RotaryConfig& c) {
  return static_cast<std::uint64_t>(floor_mod(scaled + offset, static_cast<Int128>(c.effective_range())));
}

Int128 offset_for_preset(std::uint64_t preset, Int128 scaled, const RotaryConfig& c) {
  return static_cast<Int128>(preset) - floor_mod(scaled, static_cast<Int128>(c.effective_range()));
}

}  // namespace cia406
