#include "devices/profiles/cia406/motion_estimator.h"

#include <gtest/gtest.h>

namespace cia406 {
namespace {

TEST(MotionEstimator, SpeedAccelerationJerkOverTheWindow) {
  MotionEstimator m;
  m.configure(100, 0.001);  // 100 ms
  m.reset(0);
  // Constant acceleration 1000 units/s²: x = 500 t².
  double t = 0;
  for (int i = 1; i <= 1000; ++i) {
    t = i * 0.001;
    m.push(static_cast<std::int64_t>(500 * t * t * 1000) / 1000);
  }
  EXPECT_NEAR(m.speed(), 1000 * (t - 0.05), 2.0);  // the window's mean speed
  EXPECT_NEAR(m.acceleration(), 1000, 25);
  EXPECT_NEAR(m.jerk(), 0, 300);
  // Standstill: everything decays to 0 within three windows.
  for (int i = 0; i < 300; ++i) m.push(500);
  EXPECT_EQ(m.speed(), 0.0);
  EXPECT_EQ(m.acceleration(), 0.0);
  EXPECT_EQ(m.jerk(), 0.0);
}

TEST(MotionEstimator, ResetStartsFromStandstill) {
  MotionEstimator m;
  m.configure(10, 0.001);
  m.reset(1000000);
  m.push(1000000);
  EXPECT_EQ(m.speed(), 0.0);
  m.push(1000010);
  EXPECT_DOUBLE_EQ(m.speed(), 10 / 0.010);
}

}  // namespace
}  // namespace cia406
