// The samples a plot keeps, bounded: at most kMaxPoints points per series however long the run.
// Consecutive samples are grouped into buckets; each bucket keeps, per series, its minimum and
// maximum (in the order they occurred) at the bucket's first and last time, so spikes and the
// envelope survive. When the buckets are full, neighbours merge pairwise and buckets hold twice as
// many samples. Storage is allocated once (reserve()), never per sample.
#pragma once

#include <cstddef>
#include <vector>

namespace scenario {

class PlotSamples {
 public:
  static constexpr std::size_t kMaxBuckets = 2048;
  static constexpr std::size_t kMaxPoints = 2 * kMaxBuckets;

  /// Sizes the store for `series` series (before the first add()).
  void reserve(std::size_t series);
  /// One row: the time and one value per series (NaN = no value).
  void add(double time, const double* values);

  /// The plotted points: one per bucket of one sample, two (first and last time) otherwise.
  std::vector<double> times() const;
  std::vector<double> series(std::size_t index) const;
  std::size_t samples() const { return samples_; }
  std::size_t samples_per_bucket() const { return stride_; }

 private:
  struct Extremes {
    double min, max;
    bool min_first;  // the minimum occurred before the maximum
  };
  Extremes& at(std::size_t bucket, std::size_t s) { return extremes_[bucket * series_ + s]; }
  const Extremes& at(std::size_t bucket, std::size_t s) const { return extremes_[bucket * series_ + s]; }
  void merge_pairs();

  std::size_t series_ = 0;
  std::size_t stride_ = 1;    // samples per full bucket
  std::size_t buckets_ = 0;   // buckets in use (the last one may be filling)
  std::size_t samples_ = 0;
  std::vector<double> first_time_, last_time_;
  std::vector<std::size_t> count_;
  std::vector<Extremes> extremes_;
};

}  // namespace scenario
