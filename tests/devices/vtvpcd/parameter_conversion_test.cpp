// The manual's conversion rule raw = round(EU * scale), EU = raw / scale, with the printed scales
// as exact fractions (digest §2.8) and the arithmetic of the test vectors.
#include "devices/vtvpcd/parameter_conversion.h"

#include <gtest/gtest.h>

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
