// Integer arithmetic the encoder profile needs: floor division and a modulo that is never
// negative (position wrap-around counts down from 0 to range-1), on values wide enough for a
// 2^39-revolution counter times a 16384-step resolution.
#pragma once

#include <cstdint>

namespace cia406 {

__extension__ typedef __int128 Int128;

/// Rounds toward minus infinity (b > 0).
Int128 floor_div(Int128 a, Int128 b);
/// a mod m in [0, m) (m > 0).
Int128 floor_mod(Int128 a, Int128 m);
/// Converts to int16 saturating at [low, high] (speed values must not wrap); NaN gives 0.
std::int16_t saturate_i16(double v, double low = -32768.0, double high = 32767.0);
/// Two's complement truncation to 32 bits (what an INTEGER32 object shows of a wider value).
std::int32_t truncate_i32(Int128 v);

}  // namespace cia406
