// Samples chosen signals at a fixed period: streams them to the CSV file (through a fixed 64 KiB
// buffer, written out when full: memory stays flat however long the run) and keeps the series the
// plots need, bounded by PlotSamples (at most PlotSamples::kMaxPoints points per series). Runs after the devices and before the plant in each tick, so a row holds the plant
// state at `now` and the device outputs commanded for [now, now + dt].
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "sim/scheduler.h"
#include "engine/reporting/plot_samples.h"
#include "engine/running/signal_source.h"

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
  /// Flushes and closes the CSV file; returns the first write error ("cannot write 'PATH':
  /// reason"), empty if every row reached the file. Rows after an error are not written.
  std::string close();
  /// The first CSV write error, empty while every write succeeded.
  const std::string& error() const { return error_; }

  /// The plot points of the kept signals (decimated, see PlotSamples).
  std::vector<double> times() const { return plot_.times(); }
  std::vector<double> series(int column) const;
  std::size_t rows() const { return rows_; }
  bool empty() const { return signals_.empty(); }

 private:
  sim::Duration period_;
  sim::Time next_{};
  std::vector<Signal> signals_;
  std::vector<bool> keep_;
  std::vector<bool> in_csv_;
  void fail(int err);

  std::vector<int> kept_index_;  // column → its series in plot_, -1 if not kept
  std::vector<double> kept_row_;  // one row of kept values (sized by add(), reused every sample)
  PlotSamples plot_;
  std::FILE* csv_ = nullptr;
  std::string csv_path_;
  std::string error_;
  std::vector<char> buffer_;
  std::size_t rows_ = 0;
};

}  // namespace scenario
