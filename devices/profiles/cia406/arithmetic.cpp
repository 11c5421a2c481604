#include "devices/profiles/cia406/arithmetic.h"

#include <cmath>

namespace cia406 {

Int128 floor_div(Int128 a, Int128 b) {
  Int128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

Int128 floor_mod(Int128 a, Int128 m) {
  Int128 r = a % m;
  if (r < 0) r += m;
  return r;
}

std::int16_t saturate_i16(double v, double low, double high) {
  if (std::isnan(v)) return 0;
  if (v > high) return static_cast<std::int16_t>(high);
  if (v < low) return static_cast<std::int16_t>(low);
  return static_cast<std::int16_t>(v);
}

std::int32_t truncate_i32(Int128 v) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(v) & 0xFFFFFFFFu));
}

}  // namespace cia406
