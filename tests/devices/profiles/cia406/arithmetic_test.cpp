// CiA 406 integer arithmetic: floor division and non-negative modulo, on 64-bit values (the fast
// path) and on values beyond 64 bits (the 128-bit path), at the boundaries between them.
#include "devices/profiles/cia406/arithmetic.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace cia406 {
namespace {

void expect_floor(Int128 a, Int128 b) {
  const Int128 q = floor_div(a, b);
  const Int128 r = floor_mod(a, b);
  // q = floor(a / b) and r = a - q*b in [0, b): the definition, whichever path computed them.
  EXPECT_TRUE(q * b <= a && a < (q + 1) * b) << static_cast<long double>(a) << " / " << static_cast<long double>(b);
  EXPECT_TRUE(r >= 0 && r < b);
  EXPECT_TRUE(q * b + r == a);
}

TEST(Arithmetic, FloorDivisionAndModuloOnEitherSideOf64Bits) {
  const Int128 big = static_cast<Int128>(1) << 80;
  const std::vector<Int128> numerators = {0, 1, -1, 7, -7, 16383, -16384, INT64_MAX, INT64_MIN,
                                          static_cast<Int128>(INT64_MAX) + 1, static_cast<Int128>(INT64_MIN) - 1,
                                          big, -big, big + 12345, -big - 12345};
  const std::vector<Int128> divisors = {1, 2, 3, 4, 65536, 16384, 360000, INT64_MAX,
                                        static_cast<Int128>(INT64_MAX) + 1, big};
  for (Int128 a : numerators)
    for (Int128 b : divisors) expect_floor(a, b);
  std::mt19937_64 rng(406);
  for (int i = 0; i < 2000; ++i) {
    const auto a = static_cast<std::int64_t>(rng());
    const auto b = static_cast<std::int64_t>(rng() >> (1 + i % 62)) | 1;
    expect_floor(a, b);
    expect_floor(static_cast<Int128>(a) * 65536, b);  // the WDGA's fixed-point filter values
  }
  EXPECT_EQ(floor_div(-1, 65536), -1);
  EXPECT_EQ(floor_mod(-1, 16384), 16383);
  EXPECT_EQ(floor_div(INT64_MIN, 1), INT64_MIN);
}

}  // namespace
}  // namespace cia406
