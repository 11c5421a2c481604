// CiA 406 rotary arithmetic: the digest's worked examples, and a seeded property test against
// the formula written out independently (§4.1-§4.5 of the WDGA digest).
#include "devices/profiles/cia406/rotary_position.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace cia406 {
namespace {

Int128 ref_fdiv(Int128 a, Int128 b) {
  Int128 q = a / b;
  if (a % b != 0 && (a < 0) != (b < 0)) --q;
  return q;
}
Int128 ref_mod(Int128 a, Int128 m) { return a - ref_fdiv(a, m) * m; }

RotaryConfig config(bool mt, std::uint16_t op, std::uint32_t mur, std::uint64_t tmr) {
  RotaryConfig c;
  c.multiturn = mt;
  c.operating_parameters = op;
  c.measuring_units_per_revolution = mur;
  c.total_measuring_range = tmr;
  return c;
}

TEST(RotaryPosition, WrapExampleFromTheDigest) {
  // MUR 4096, TMR 10000, preset 9990, +20 steps → 10, then −30 → 9980.
  const auto c = config(true, kScalingFunction, 4096, 10000);
  const std::int64_t p0 = 12345;  // any physical count
  const Int128 s0 = scaled_count(p0, c);
  const Int128 offset = offset_for_preset(9990, s0, c);
  EXPECT_EQ(output_position(s0, offset, c), 9990u);
  EXPECT_EQ(output_position(s0 + 20, offset, c), 10u);
  EXPECT_EQ(output_position(s0 - 10, offset, c), 9980u);
}

TEST(RotaryPosition, CodeSequenceAndScalingOff) {
  const auto cw = config(true, 0, 16384, 0);
  EXPECT_EQ(scaled_count(100, cw), 100);
  const auto ccw = config(true, kCodeSequenceCounterClockwise, 16384, 0);
  EXPECT_EQ(scaled_count(100, ccw), -100);
  EXPECT_EQ(ccw.effective_range(), 16384ull << 39);
  EXPECT_EQ(output_position(-100, 0, ccw), (16384ull << 39) - 100);
  const auto st = config(false, kCodeSequenceCounterClockwise, 16384, 0);
  EXPECT_EQ(scaled_count(100, st), 16284);
  EXPECT_EQ(st.effective_range(), 16384u);
}

TEST(RotaryPosition, PhysicalCountIsTheFloorOfTheAngle) {
  RotaryConfig c;
  EXPECT_EQ(physical_count(1.0, c), 16384);
  EXPECT_EQ(physical_count(-0.5 / 16384, c), -1);
  c.multiturn = false;
  EXPECT_EQ(physical_count(-0.25, c), 12288);
  EXPECT_EQ(physical_count(7.25, c), 4096);
}

TEST(RotaryPosition, WithinTurnReducesSingleturnCounts) {
  const auto st = config(false, kScalingFunction, 1000, 360);
  EXPECT_EQ(within_turn(2500, st), 500);
  EXPECT_EQ(within_turn(-1, st), 999);
  const auto mt = config(true, kScalingFunction, 1000, 360);
  EXPECT_EQ(within_turn(-1, mt), -1);
}

TEST(RotaryPositionProperty, MatchesTheFormulaForRandomConfigurations) {
  std::mt19937_64 rng(406);
  auto rnd = [&](std::uint64_t lo, std::uint64_t hi) { return std::uniform_int_distribution<std::uint64_t>(lo, hi)(rng); };
  for (int trial = 0; trial < 20000; ++trial) {
    const bool mt = rnd(0, 3) != 0;
    const std::uint16_t op = static_cast<std::uint16_t>((rnd(0, 1) ? kCodeSequenceCounterClockwise : 0) |
                                                        (rnd(0, 4) ? kScalingFunction : 0));
    const auto mur = static_cast<std::uint32_t>(rnd(1, 16384));
    const std::uint64_t tmr = mt ? rnd(1, 1ull << 32) : rnd(1, mur);
    const auto c = config(mt, op, mur, tmr);
    const auto p = static_cast<std::int64_t>(rnd(0, 1ull << 54)) - (1ll << 53);
    // The formula.
    Int128 pp = mt ? Int128{p} : ref_mod(p, 16384);
    Int128 pd = (op & kCodeSequenceCounterClockwise) ? -pp : pp;
    if (!mt) pd = ref_mod(pd, 16384);
    const Int128 s = (op & kScalingFunction) ? ref_fdiv(pd * mur, 16384) : pd;
    const Int128 range = (op & kScalingFunction) ? Int128(tmr) : (mt ? Int128(16384) << 39 : Int128(16384));
    ASSERT_EQ(scaled_count(p, c), s) << trial;
    ASSERT_EQ(static_cast<std::uint64_t>(c.effective_range()), static_cast<std::uint64_t>(range));
    const std::uint64_t preset = rnd(0, static_cast<std::uint64_t>(range) - 1);
    const Int128 offset = offset_for_preset(preset, s, c);
    ASSERT_EQ(offset, Int128(preset) - ref_mod(s, range));
    ASSERT_EQ(output_position(s, offset, c), preset);  // a preset reads back exactly
    const auto move = static_cast<std::int64_t>(rnd(0, 1ull << 40)) - (1ll << 39);
    const Int128 s2 = scaled_count(p + move, c);
    ASSERT_EQ(output_position(s2, offset, c), static_cast<std::uint64_t>(ref_mod(s2 + offset, range)));
  }
}

}  // namespace
}  // namespace cia406

namespace cia406 {
namespace {

TEST(RotaryPosition, PowerOfTwoResolutionScalesAsTheFloorDivision) {
  // scaled_count() shifts for a power-of-two resolution: the same count as floor(S·MUR/res) for
  // either sign, beyond 64 bits, and for a resolution that is no power of two.
  std::mt19937_64 rng(6001);
  for (std::uint32_t res : {16384u, 1u, 2u, 4096u, 1u << 31, 10000u, 3u}) {
    for (int i = 0; i < 3000; ++i) {
      RotaryConfig c = config(true, kScalingFunction, static_cast<std::uint32_t>(rng() >> (i % 40)) | 1, 1ull << 30);
      c.physical_resolution = res;
      const auto physical = static_cast<std::int64_t>(rng()) >> (i % 60);
      if (i % 2) c.operating_parameters |= kCodeSequenceCounterClockwise;
      const Int128 directed = c.counter_clockwise() ? -static_cast<Int128>(physical) : static_cast<Int128>(physical);
      ASSERT_EQ(scaled_count(physical, c), ref_fdiv(directed * c.measuring_units_per_revolution, res)) << res << " " << i;
    }
  }
}

TEST(Arithmetic, SaturatingATruncatedValueIsSaturatingTheValue) {
  // The WDGA publishes speed, acceleration and jerk as saturate_i16(v) with integer bounds, which
  // is saturate_i16(trunc(v)) without the library call.
  std::mt19937_64 rng(6030);
  std::vector<double> vs = {0.0, -0.0, 0.5, -0.5, 32766.9, 32767.0, 32767.5, 32768.0, -32766.9, -32767.0,
                            -32767.5, -32768.0, -32768.5, 1e300, -1e300, std::nan(""),
                            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 20000; ++i) vs.push_back((static_cast<double>(rng() >> 11) / 9007199254740992.0 - 0.5) * 140000.0);
  for (double v : vs) {
    EXPECT_EQ(saturate_i16(v, -32767, 32767), saturate_i16(std::trunc(v), -32767, 32767)) << v;
    EXPECT_EQ(saturate_i16(v), saturate_i16(std::trunc(v))) << v;
  }
}

}  // namespace
}  // namespace cia406
