#include "devices/profiles/cia406/arithmetic.h"

#include <cmath>
#include <cstdint>

namespace cia406 {

namespace {
// Most counts fit 64 bits: the 64-bit division gives the same quotient at a fraction of the cost
// of the 128-bit library call. -1 is left out (INT64_MIN / -1 overflows).
bool fits_64(Int128 v) { return v >= INT64_MIN && v <= INT64_MAX; }
bool narrow(Int128 a, Int128 b) { return fits_64(a) && fits_64(b) && b != -1; }
}  // namespace

Int128 floor_div(Int128 a, Int128 b) {
  if (narrow(a, b)) {
    const auto x = static_cast<std::int64_t>(a), y = static_cast<std::int64_t>(b);
    std::int64_t q = x / y;
    if ((x % y != 0) && ((x < 0) != (y < 0))) --q;
    return q;
  }
  Int128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

Int128 floor_mod(Int128 a, Int128 m) {
  if (narrow(a, m)) {
    std::int64_t r = static_cast<std::int64_t>(a) % static_cast<std::int64_t>(m);
    if (r < 0) r += static_cast<std::int64_t>(m);
    return r;
  }
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
