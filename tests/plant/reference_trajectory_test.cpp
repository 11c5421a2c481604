// The 20 s reference-plant trajectory against the one recorded before the speed work (issue 14):
// positions, speeds and pressures within 0.5 % of each signal's range (RMS), and the cylinder
// reaching its end stops at the same ticks, give or take one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "plant_test_support.h"
#include "reference_trajectory.h"

namespace plant {
namespace {

using namespace plant::testing;

struct StoredTrajectory {
  std::vector<long> stops;
  std::vector<std::vector<double>> columns;  // per signal
};

StoredTrajectory load(const std::string& path) {
  StoredTrajectory out;
  out.columns.resize(kTrajectorySignals.size());
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot open " << path;
  std::string line;
  std::getline(in, line);
  std::istringstream stops(line.substr(line.find(':') + 1));
  for (long s; stops >> s;) out.stops.push_back(s);
  std::getline(in, line);  // header
  std::string expected_header;
  for (std::size_t i = 0; i < kTrajectorySignals.size(); ++i) expected_header += (i ? "," : "") + std::string(kTrajectorySignals[i]);
  EXPECT_EQ(line, expected_header);
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    for (auto& column : out.columns) {
      std::getline(row, cell, ',');
      column.push_back(std::strtod(cell.c_str(), nullptr));
    }
  }
  return out;
}

TEST(ReferenceTrajectory, MatchesTheTrajectoryRecordedBeforeTheSpeedWork) {
  const StoredTrajectory before = load(VPLANT_SOURCE_DIR "/tests/data/plant/reference_trajectory.csv");
  const RecordedTrajectory now = record_reference_trajectory();
  ASSERT_EQ(before.columns.front().size(), now.samples.size());
  for (std::size_t s = 0; s < kTrajectorySignals.size(); ++s) {
    const auto& b = before.columns[s];
    const auto [lo, hi] = std::minmax_element(b.begin(), b.end());
    const double range = *hi - *lo;
    ASSERT_GT(range, 0.0) << kTrajectorySignals[s];
    double square = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const double d = now.samples[i][s] - b[i];
      square += d * d;
    }
    const double rms = std::sqrt(square / static_cast<double>(b.size())) / range;
    RecordProperty(std::string(kTrajectorySignals[s]) + "_rms", figure(rms));
    EXPECT_LT(rms, 0.005) << kTrajectorySignals[s] << ": RMS deviation " << rms << " of its range";
  }
  // Four stroke ends per 10 s cycle: upper, lower, twice.
  ASSERT_EQ(before.stops.size(), 4u);
  ASSERT_EQ(now.stop_arrivals.size(), before.stops.size());
  for (std::size_t i = 0; i < before.stops.size(); ++i) {
    EXPECT_EQ(now.stop_arrivals[i] > 0, before.stops[i] > 0) << "stop arrival " << i;
    EXPECT_LE(std::abs(std::abs(now.stop_arrivals[i]) - std::abs(before.stops[i])), 1)
        << "stop arrival " << i << ": tick " << std::abs(now.stop_arrivals[i]) << ", before " << std::abs(before.stops[i]);
  }
}

}  // namespace
}  // namespace plant
