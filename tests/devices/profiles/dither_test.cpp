// Dither: square wave, peak-to-peak amplitude, frequency from the simulation clock.
#include "devices/profiles/dsp408/dither.h"

#include <gtest/gtest.h>

using dsp408::Dither;

namespace {
sim::Time at_us(std::int64_t us) { return sim::Time{sim::microseconds(us)}; }
}  // namespace

TEST(Dither, SquareWaveHalfPeriodsAtTheFrequency) {
  Dither d;
  d.configure(Dither::Shape::Square, 100, 0.05);  // 100 Hz, 50 mA peak-to-peak
  for (int ms = 0; ms < 20; ++ms) {
    const double expected = (ms % 10) < 5 ? 0.025 : -0.025;
    EXPECT_DOUBLE_EQ(d.offset(at_us(ms * 1000)), expected) << ms;
  }
  EXPECT_DOUBLE_EQ(d.apply(0.5, at_us(0), 1.5), 0.525);
  EXPECT_DOUBLE_EQ(d.apply(0.5, at_us(5000), 1.5), 0.475);
}

TEST(Dither, OffWhenTheSolenoidIsOffAndLimited) {
  Dither d;
  d.configure(Dither::Shape::Square, 500, 0.2);
  EXPECT_EQ(d.apply(0, at_us(0), 1.5), 0);
  EXPECT_EQ(d.apply(1.45, at_us(0), 1.5), 1.5);
  EXPECT_EQ(d.apply(0.05, at_us(1000), 1.5), 0);
  d.configure(Dither::Shape::Off, 500, 0.2);
  EXPECT_EQ(d.offset(at_us(0)), 0);
}

TEST(Dither, SineHasThePeakAtAQuarterPeriod) {
  Dither d;
  d.configure(Dither::Shape::Sine, 50, 0.1);
  EXPECT_NEAR(d.offset(at_us(5000)), 0.05, 1e-12);
  EXPECT_NEAR(d.offset(at_us(15000)), -0.05, 1e-12);
}
