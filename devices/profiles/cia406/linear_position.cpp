#include "devices/profiles/cia406/linear_position.h"

#include <algorithm>
#include <cmath>

#include "devices/profiles/cia406/arithmetic.h"

namespace cia406 {

std::int64_t steps_from_metres(double metres, const LinearConfig& c) {
  const double steps = round_half_away(metres * 1e9 / static_cast<double>(c.step_nm));  // = std::round
  if (!(steps > 0)) return 0;  // also NaN
  return std::min<std::int64_t>(static_cast<std::int64_t>(std::min(steps, 9.0e18)), c.steps - 1);
}

std::int64_t directed_raw(std::int64_t steps, const LinearConfig& c) { return c.decreasing ? (c.steps - 1) - steps : steps; }

std::int64_t linear_position(std::int64_t raw, std::int64_t offset, const LinearConfig& c) {
  return raw + c.manufacturer_offset + offset;
}

std::int64_t linear_offset_for_preset(std::int64_t preset, std::int64_t raw, const LinearConfig& c) {
  return preset - (raw + c.manufacturer_offset);
}

}  // namespace cia406
