// Writes the reference-plant trajectory (reference_trajectory.h) as the CSV the
// reference_trajectory test compares against: the stop arrivals as one "# stops:" line, then a
// header and one row per sample. Usage: reference_trajectory_dump > reference_trajectory.csv
#include <cstdio>

#include "reference_trajectory.h"

int main() {
  const auto t = plant::testing::record_reference_trajectory();
  std::printf("# stops:");
  for (long s : t.stop_arrivals) std::printf(" %ld", s);
  std::printf("\n");
  for (std::size_t i = 0; i < plant::testing::kTrajectorySignals.size(); ++i)
    std::printf("%s%s", i ? "," : "", plant::testing::kTrajectorySignals[i]);
  std::printf("\n");
  for (const auto& row : t.samples) {
    for (std::size_t i = 0; i < row.size(); ++i) std::printf("%s%.9g", i ? "," : "", row[i]);
    std::printf("\n");
  }
  return 0;
}
