// The manual's conversion rule raw = round(EU * scale), EU = raw / scale, with the printed scales
// as exact fractions (digest §2.8) and the arithmetic of the test vectors.
#include "devices/vtvpcd/parameter_conversion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace vtvpcd;

TEST(ParameterConversion, ManualExamplePowerCmd4PercentIs1311) {
  // (4.0 - 0) * 327.67 = 1310.68, arithmetically rounded 1311 = 0x051F (manual §3.3).
  EXPECT_EQ(to_raw(4.0, kScalePercent), 1311);
  EXPECT_EQ(to_raw(4.0, kScalePercent), 0x051F);
}

TEST(ParameterConversion, HalfwayCasesRoundAwayFromZero) {
  EXPECT_EQ(to_raw(50.0, kScalePercent), 16384);    // 16383.5 exactly (TV20)
  EXPECT_EQ(to_raw(-50.0, kScalePercent), -16384);  // TV11
  EXPECT_EQ(to_raw(2.5, kScaleRamp), 313);          // 312.5 (TV14)
  EXPECT_EQ(to_raw(-1.5, kScaleValveZero), -225);   // TV17
}

TEST(ParameterConversion, DigestVectors) {
  EXPECT_EQ(to_raw(210.0, kScaleTable), 68817);     // Press. CMD binary 3 (TV15)
  EXPECT_EQ(to_raw(210.0, kScalePercent), 68811);   // act. pressure B (TV21)
  EXPECT_EQ(to_raw(2.0, kScaleRamp), 250);          // TV13
  EXPECT_EQ(to_raw(1.5, kScaleGain), 192);          // TV16
  EXPECT_EQ(to_raw(100.0, kScaleLvdtGain), 1260);   // TV18
  EXPECT_EQ(to_raw(120.0, kScalePercent), 39320);   // TV38 (39320.4)
  EXPECT_EQ(to_raw(75.0, kScalePercent), 24575);    // TV39 (24575.25)
  EXPECT_EQ(to_raw(60.0, kScaleTable), 19662);      // TV39
  EXPECT_EQ(to_raw(40.0, kScaleTable), 13108);      // checklist 38
  EXPECT_EQ(to_raw(350.0, kScalePercent), 114685);  // start-up Pressure CMD (BUS)
  EXPECT_EQ(to_raw(350.0, kScaleTable), 114695);    // start-up Press. CMD binary k
  EXPECT_EQ(to_raw(100.0, kScaleTable), 32770);
  EXPECT_EQ(to_raw(100.0, kScalePercent), 32767);
}

TEST(ParameterConversion, RawToEngineeringUnits) {
  EXPECT_DOUBLE_EQ(to_eu(32767, kScalePercent), 100.0);
  EXPECT_DOUBLE_EQ(to_eu(250, kScaleRamp), 2.0);
  EXPECT_DOUBLE_EQ(to_eu(1260, kScaleLvdtGain), 100.0);
  EXPECT_DOUBLE_EQ(to_eu(-1800, kScaleValveZero), -12.0);
  EXPECT_NEAR(to_eu(114685, kScalePercent), 350.0, 2e-3);
}

TEST(ParameterConversion, SaturatesToTheBusInteger) {
  EXPECT_EQ(to_raw(1e12, kScalePercent), 2147483647);
  EXPECT_EQ(to_raw(-1e12, kScalePercent), -2147483647 - 1);
  EXPECT_EQ(to_raw(1e9, kScaleOne, 0, 65535), 65535);
  EXPECT_EQ(to_raw(std::nan(""), kScalePercent), 0);
}

TEST(ParameterConversion, RoundingIsTheFloorFormulaBitForBit) {
  // round_half_away() truncates instead of calling floor(): the same double, sign of zero included.
  auto reference = [](double x) { return x < 0 ? -std::floor(-x + 0.5) : std::floor(x + 0.5); };
  std::vector<double> xs = {0.0, -0.0, 0.49999999999999994, 0.5, -0.5, 1.5, -1.5, 2.5, 16383.5, -16383.5,
                            4503599627370495.5, 4503599627370496.0, 9007199254740993.0, 9.2233720368547e18,
                            9223372036854775808.0, -9223372036854775808.0, 1e300, -1e300,
                            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min()};
  std::uint64_t state = 12345;
  for (int i = 0; i < 100000; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const double unit = static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
    xs.push_back((unit - 0.5) * std::pow(10.0, static_cast<double>(i % 24) - 4.0));
    xs.push_back(std::nextafter(std::round(xs.back()) + 0.5, 0.0));
  }
  for (double x : xs) {
    const double got = round_half_away(x), want = reference(x);
    EXPECT_EQ(std::signbit(got), std::signbit(want)) << x;
    EXPECT_EQ(got, want) << x;
  }
  EXPECT_TRUE(std::isnan(round_half_away(std::nan(""))));
}
