#include "devices/profiles/dsp408/dither.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace dsp408 {

std::int64_t Dither::milli_hz(double frequency_hz) {
  return frequency_hz > 0 ? static_cast<std::int64_t>(std::llround(frequency_hz * 1000)) : 0;
}

double Dither::offset(sim::Time t) const {
  if (shape_ == Shape::Off || frequency_ <= 0 || amplitude_ <= 0) return 0;
  // Exact phase for frequencies in whole mHz: (t[µs] · f[mHz]) mod 10^9.
  const std::int64_t milli_hz = milli_hz_;
  constexpr std::int64_t kCycle = 1'000'000'000;
  const std::int64_t us = t.time_since_epoch().count();
  const double phase = static_cast<double>(((us % kCycle) * milli_hz) % kCycle) / static_cast<double>(kCycle);
  if (shape_ == Shape::Square) return phase < 0.5 ? amplitude_ / 2 : -amplitude_ / 2;
  return amplitude_ / 2 * std::sin(2 * std::numbers::pi * phase);
}

}  // namespace dsp408
