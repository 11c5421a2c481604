// The recorder: CSV rows streamed through a fixed buffer, write failures reported, plot samples
// bounded.
#include "engine/reporting/recorder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/support/temp_path.h"

namespace {

struct Counter {
  double value = 0;
};

scenario::Signal signal_of(const std::string& name, const Counter& c) {
  return scenario::Signal::port(&c.value, 1.0, 0.0, name);
}

}  // namespace

TEST(Recorder, CsvOnAFullDeviceReportsPathAndReason) {
  Counter c;
  scenario::Recorder r(sim::milliseconds(1));
  r.add(signal_of("x", c), false, true);
  ASSERT_EQ(r.open_csv("/dev/full"), "");
  for (int i = 0; i < 10000; ++i) {  // more than the 64 KiB buffer: the failure shows during the run
    c.value = i;
    r.step(sim::Time{} + sim::milliseconds(i), sim::milliseconds(1));
  }
  EXPECT_EQ(r.error(), "cannot write '/dev/full': No space left on device");
  EXPECT_EQ(r.close(), "cannot write '/dev/full': No space left on device");
}

TEST(Recorder, CsvFailureAtTheLastFlushIsReported) {
  Counter c;
  scenario::Recorder r(sim::milliseconds(1));
  r.add(signal_of("x", c), false, true);
  ASSERT_EQ(r.open_csv("/dev/full"), "");
  r.step(sim::Time{}, sim::milliseconds(1));
  EXPECT_EQ(r.error(), "");  // one row, still buffered
  EXPECT_EQ(r.close(), "cannot write '/dev/full': No space left on device");
}

TEST(Recorder, StreamsEveryRowAndKeepsPlotsBounded) {
  const std::string path = vtest::unique_temp_path("vplant-recorder", ".csv");
  Counter c;
  scenario::Recorder r(sim::milliseconds(1));
  const int col = r.add(signal_of("x", c), true, true);
  ASSERT_EQ(r.open_csv(path), "");
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    c.value = i == 50000 ? -1e6 : i;  // one spike that the plot must keep
    r.step(sim::Time{} + sim::milliseconds(i), sim::milliseconds(1));
  }
  EXPECT_EQ(r.close(), "");
  EXPECT_EQ(r.rows(), static_cast<std::size_t>(n));
  std::ifstream in(path);
  int lines = 0;
  for (std::string l; std::getline(in, l);) ++lines;
  EXPECT_EQ(lines, n + 1);  // header + every row
  std::remove(path.c_str());

  const auto t = r.times();
  const auto v = r.series(col);
  ASSERT_EQ(t.size(), v.size());
  EXPECT_LE(v.size(), scenario::PlotSamples::kMaxPoints);
  EXPECT_EQ(*std::min_element(v.begin(), v.end()), -1e6);
  EXPECT_EQ(*std::max_element(v.begin(), v.end()), n - 1);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.back(), (n - 1) * 1e-3);
}
