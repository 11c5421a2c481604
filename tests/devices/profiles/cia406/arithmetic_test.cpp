// CiA 406 integer arithmetic: floor division and non-negative modulo, on 64-bit values (the fast
// path) and on values beyond 64 bits (the 128-bit path), at the boundaries between them.
#include "devices/profiles/cia406/arithmetic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
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

TEST(Arithmetic, RoundingIsTheLibrarysBitForBit) {
  std::vector<double> xs = {0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                            0.3, -0.3, 4503599627370495.5, -4503599627370495.5, 4503599627370496.0, 9007199254740993.0,
                            1e300, -1e300, std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  std::mt19937_64 rng(1100);
  for (int i = 0; i < 100000; ++i) {
    const double unit = static_cast<double>(rng() >> 11) / 9007199254740992.0 - 0.5;
    xs.push_back(unit * std::pow(10.0, static_cast<double>(i % 20) - 3.0));
    xs.push_back(std::floor(xs.back()) + 0.5);
    xs.push_back(std::nextafter(xs.back(), 0.0));
  }
  for (double x : xs) {
    const double r = round_half_away(x);
    ASSERT_EQ(r, std::round(x)) << x;
    ASSERT_EQ(std::signbit(r), std::signbit(std::round(x))) << x;
    if (std::fabs(x) < 9e18) {
      ASSERT_EQ(llround_half_away(x), std::llround(x)) << x;
    }
  }
  EXPECT_TRUE(std::isnan(round_half_away(std::nan(""))));
}

}  // namespace
}  // namespace cia406
