#include "engine/reporting/speed_text.h"

#include <gtest/gtest.h>

using scenario::real_time_factor_text;

// 5 s simulated in 8.3 s of wall time is slower than real time: not "1× real time".
TEST(SpeedText, BelowTenTimesRealTimeHasADecimal) {
  EXPECT_EQ(real_time_factor_text(5.0, 8.3), "0.6× real time");
  EXPECT_EQ(real_time_factor_text(10.0, 10.0), "1.0× real time");
  EXPECT_EQ(real_time_factor_text(9.0, 1.0), "9.0× real time");
  EXPECT_EQ(real_time_factor_text(120.0, 1.0), "120× real time");
  EXPECT_EQ(real_time_factor_text(1.0, 0.0), "no wall time elapsed");
}
