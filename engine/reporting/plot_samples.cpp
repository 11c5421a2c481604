#include "engine/reporting/plot_samples.h"

#include <cmath>
#include <limits>

namespace scenario {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// NaN-aware: a bucket's extreme is NaN only while every sample in it was NaN.
bool less(double a, double b) { return std::isnan(b) ? !std::isnan(a) : a < b; }
bool greater(double a, double b) { return std::isnan(b) ? !std::isnan(a) : a > b; }

}  // namespace

void PlotSamples::reserve(std::size_t series) {
  series_ = series;
  first_time_.assign(kMaxBuckets, 0.0);
  last_time_.assign(kMaxBuckets, 0.0);
  count_.assign(kMaxBuckets, 0);
  extremes_.assign(kMaxBuckets * series, Extremes{kNaN, kNaN, true});
}

void PlotSamples::add(double time, const double* values) {
  if (buckets_ == 0 || count_[buckets_ - 1] == stride_) {
    if (buckets_ == kMaxBuckets) merge_pairs();
    const std::size_t b = buckets_++;
    first_time_[b] = time;
    count_[b] = 0;
    for (std::size_t s = 0; s < series_; ++s) at(b, s) = {values[s], values[s], true};
  }
  const std::size_t b = buckets_ - 1;
  last_time_[b] = time;
  ++count_[b];
  for (std::size_t s = 0; s < series_; ++s) {
    auto& e = at(b, s);
    const double v = values[s];
    if (less(v, e.min)) {
      e.min = v;
      e.min_first = false;  // the new minimum comes after the maximum so far
    }
    if (greater(v, e.max)) {
      e.max = v;
      e.min_first = true;
    }
  }
  ++samples_;
}

void PlotSamples::merge_pairs() {
  for (std::size_t i = 0; i < buckets_ / 2; ++i) {
    const std::size_t a = 2 * i, b = 2 * i + 1;
    first_time_[i] = first_time_[a];
    last_time_[i] = last_time_[b];
    count_[i] = count_[a] + count_[b];
    for (std::size_t s = 0; s < series_; ++s) {
      const Extremes ea = at(a, s), eb = at(b, s);
      const bool min_in_b = less(eb.min, ea.min);
      const bool max_in_b = greater(eb.max, ea.max);
      Extremes m{min_in_b ? eb.min : ea.min, max_in_b ? eb.max : ea.max, true};
      if (min_in_b == max_in_b) {
        m.min_first = min_in_b ? eb.min_first : ea.min_first;
      } else {
        m.min_first = !min_in_b;  // the one in the earlier bucket came first
      }
      at(i, s) = m;
    }
  }
  buckets_ /= 2;
  stride_ *= 2;
}

std::vector<double> PlotSamples::times() const {
  std::vector<double> t;
  t.reserve(2 * buckets_);
  for (std::size_t b = 0; b < buckets_; ++b) {
    t.push_back(first_time_[b]);
    if (count_[b] > 1) t.push_back(last_time_[b]);
  }
  return t;
}

std::vector<double> PlotSamples::series(std::size_t index) const {
  std::vector<double> v;
  v.reserve(2 * buckets_);
  for (std::size_t b = 0; b < buckets_; ++b) {
    const auto& e = at(b, index);
    if (count_[b] == 1) {
      v.push_back(e.min);
    } else {
      v.push_back(e.min_first ? e.min : e.max);
      v.push_back(e.min_first ? e.max : e.min);
    }
  }
  return v;
}

}  // namespace scenario
