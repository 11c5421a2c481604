// Integer arithmetic the encoder profile needs: floor division and a modulo that is never
// negative (position wrap-around counts down from 0 to range-1), on values wide enough for a
// 2^39-revolution counter times a 16384-step resolution. Inline: the encoders run them in every
// measurement cycle.
#pragma once

#include <cmath>
#include <cstdint>

namespace cia406 {

__extension__ typedef __int128 Int128;

namespace detail {
// Most counts fit 64 bits: the 64-bit division gives the same quotient at a fraction of the cost
// of the 128-bit library call. -1 is left out (INT64_MIN / -1 overflows).
inline bool fits_64(Int128 v) { return static_cast<Int128>(static_cast<std::int64_t>(v)) == v; }
inline bool narrow(Int128 a, Int128 b) { return fits_64(a) && fits_64(b) && b != -1; }
}  // namespace detail

/// Rounds toward minus infinity (b > 0).
inline Int128 floor_div(Int128 a, Int128 b) {
  if (detail::narrow(a, b)) {
    const auto x = static_cast<std::int64_t>(a), y = static_cast<std::int64_t>(b);
    std::int64_t q = x / y;
    if ((x % y != 0) && ((x < 0) != (y < 0))) --q;
    return q;
  }
  Int128 q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}

/// a mod m in [0, m) (m > 0).
inline Int128 floor_mod(Int128 a, Int128 m) {
  if (detail::narrow(a, m)) {
    std::int64_t r = static_cast<std::int64_t>(a) % static_cast<std::int64_t>(m);
    if (r < 0) r += static_cast<std::int64_t>(m);
    return r;
  }
  Int128 r = a % m;
  if (r < 0) r += m;
  return r;
}

/// Converts to int16 saturating at [low, high] (speed values must not wrap); NaN gives 0.
inline std::int16_t saturate_i16(double v, double low = -32768.0, double high = 32767.0) {
  if (std::isnan(v)) return 0;
  if (v > high) return static_cast<std::int16_t>(high);
  if (v < low) return static_cast<std::int16_t>(low);
  return static_cast<std::int16_t>(v);
}

/// std::round(x) bit for bit (half away from zero, the sign of zero kept), without the library
/// call below 2^52, where the difference of x and its truncation is exact.
inline double round_half_away(double x) {
  if (!(std::fabs(x) < 4503599627370496.0)) return std::round(x);  // large (already integral), inf, NaN
  const auto t = static_cast<std::int64_t>(x);
  const double frac = x - static_cast<double>(t);
  const std::int64_t r = t + (frac >= 0.5) - (frac <= -0.5);
  return std::copysign(static_cast<double>(r), x);
}

/// std::llround(x) for |x| < 2^52 without the library call (the library beyond and for NaN).
inline long long llround_half_away(double x) {
  if (!(std::fabs(x) < 4503599627370496.0)) return std::llround(x);
  const auto t = static_cast<std::int64_t>(x);
  const double frac = x - static_cast<double>(t);
  return t + (frac >= 0.5) - (frac <= -0.5);
}

/// Two's complement truncation to 32 bits (what an INTEGER32 object shows of a wider value).
inline std::int32_t truncate_i32(Int128 v) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(v) & 0xFFFFFFFFu));
}

}  // namespace cia406
