// PlotSamples: a bounded number of points, the envelope (minimum and maximum) kept, in time order.
#include "engine/reporting/plot_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using scenario::PlotSamples;

TEST(PlotSamples, KeepsEverySampleWhileThereIsRoom) {
  PlotSamples p;
  p.reserve(1);
  for (int i = 0; i < 100; ++i) {
    const double v = i * 2.0;
    p.add(i * 0.1, &v);
  }
  ASSERT_EQ(p.times().size(), 100u);
  EXPECT_EQ(p.series(0)[37], 74.0);
  EXPECT_DOUBLE_EQ(p.times()[37], 3.7);
}

TEST(PlotSamples, StaysBoundedAndKeepsTheEnvelopeInOrder) {
  PlotSamples p;
  p.reserve(2);
  const int n = 1'000'000;
  for (int i = 0; i < n; ++i) {
    // Series 0: a sine with one spike up and one down; series 1: a ramp.
    double v[2] = {std::sin(i * 1e-3), static_cast<double>(i)};
    if (i == 123'457) v[0] = 50;
    if (i == 765'433) v[0] = -70;
    p.add(i * 1e-3, v);
  }
  const auto t = p.times();
  const auto s0 = p.series(0);
  const auto s1 = p.series(1);
  EXPECT_LE(t.size(), PlotSamples::kMaxPoints);
  EXPECT_GT(t.size(), PlotSamples::kMaxPoints / 4);
  ASSERT_EQ(s0.size(), t.size());
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.back(), (n - 1) * 1e-3);
  EXPECT_EQ(*std::max_element(s0.begin(), s0.end()), 50.0);
  EXPECT_EQ(*std::min_element(s0.begin(), s0.end()), -70.0);
  // The spike up comes before the spike down, as in the samples.
  const auto up = std::find(s0.begin(), s0.end(), 50.0) - s0.begin();
  const auto down = std::find(s0.begin(), s0.end(), -70.0) - s0.begin();
  EXPECT_LT(up, down);
  // A monotonic ramp stays monotonic (minimum first in every bucket).
  EXPECT_TRUE(std::is_sorted(s1.begin(), s1.end()));
  EXPECT_EQ(s1.front(), 0.0);
  EXPECT_EQ(s1.back(), n - 1);
  EXPECT_EQ(p.samples(), static_cast<std::size_t>(n));
}

TEST(PlotSamples, AFallingRampPutsTheMaximumFirst) {
  PlotSamples p;
  p.reserve(1);
  for (int i = 0; i < 20'000; ++i) {
    const double v = -i;
    p.add(i, &v);
  }
  const auto s = p.series(0);
  EXPECT_TRUE(std::is_sorted(s.rbegin(), s.rend()));
}

TEST(PlotSamples, NanOnlyWhereEverySampleWasNan) {
  PlotSamples p;
  p.reserve(1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 10'000; ++i) {
    const double v = i < 5'000 ? nan : 1.0;
    p.add(i, &v);
  }
  const auto s = p.series(0);
  EXPECT_TRUE(std::isnan(s.front()));
  EXPECT_EQ(s.back(), 1.0);
}
