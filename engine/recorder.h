// Samples chosen signals at a fixed period: streams them to the CSV file and keeps the series the
// plots need. Runs after the devices and before the plant in each tick, so a row holds the plant
// state at `now` and the device outputs commanded for [now, now + dt].
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "sim/scheduler.h"
#include "engine/signal_source.h"

namespace scenario {

class Recorder final : public sim::Steppable {
 public:
  explicit Recorder(sim::Duration period) : period_(period) {}
  ~Recorder() override;

  /// Adds a signal (once per name); `keep` = hold its samples in memory (for a plot), `csv` =
  /// write it to the CSV file. Returns its column.
  int add(const Signal& signal, bool keep, bool csv);
  /// Streams every signal to `path` as CSV; returns an error message, empty on success.
  std::string open_csv(const std::string& path);

  void step(sim::Time now, sim::Duration dt) override;
  void close();

  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& series(int column) const { return kept_[static_cast<std::size_t>(column)]; }
  std::size_t rows() const { return rows_; }
  bool empty() const { return signals_.empty(); }

 private:
  sim::Duration period_;
  sim::Time next_{};
  std::vector<Signal> signals_;
  std::vector<bool> keep_;
  std::vector<bool> in_csv_;
  std::vector<std::vector<double>> kept_;
  std::vector<double> times_;
  std::FILE* csv_ = nullptr;
  std::vector<char> buffer_;
  std::size_t rows_ = 0;
  bool any_kept_ = false;
};

}  // namespace scenario
