// devices/wdga/position_filter: the fixed-point IIR y <- y + floor((S·2^16 − y) / c), output
// floor((y + 2^15) / 2^16), computed with shifts and (for c = 1) without a division, gives the
// formula's counts for every constant 0 (taken as 1) to 4, either sign and beyond 64 bits.
#include "devices/wdga/position_filter.h"

#include <gtest/gtest.h>

#include <random>

namespace wdga {
namespace {

using cia406::Int128;

Int128 ref_fdiv(Int128 a, Int128 b) {
  Int128 q = a / b;
  if (a % b != 0 && (a < 0) != (b < 0)) --q;
  return q;
}

TEST(PositionFilter, MatchesTheFormula) {
  std::mt19937_64 rng(2105);
  for (unsigned c = 0; c <= 4; ++c) {
    PositionFilter f;
    Int128 y = 0;
    const Int128 start = static_cast<Int128>(static_cast<std::int64_t>(rng()) >> 20);
    f.reset(start);
    y = start * 65536;
    Int128 s = start;
    for (int i = 0; i < 20000; ++i) {
      const int shape = i / 5000;
      if (shape == 0) s += static_cast<std::int64_t>(rng() % 2001) - 1000;
      if (shape == 1) s = static_cast<Int128>(static_cast<std::int64_t>(rng())) * 1000;  // beyond 64 bits x 2^16
      if (shape == 2) s = -s - 1;
      if (shape == 3) s += 1;
      y += ref_fdiv(s * 65536 - y, c == 0 ? 1 : c);
      const Int128 want = ref_fdiv(y + 32768, 65536);
      ASSERT_TRUE(f.update(s, c) == want) << "c " << c << " step " << i;
    }
  }
}

}  // namespace
}  // namespace wdga
