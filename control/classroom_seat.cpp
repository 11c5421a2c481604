#include "control/classroom_seat.h"

#include <algorithm>

#include "sim/scheduler.h"

namespace control {

void LatenessHistogram::add(std::int64_t lateness_us) {
  const auto us = std::max<std::int64_t>(lateness_us, 0);
  const auto bucket = std::min<std::size_t>(static_cast<std::size_t>(us / kBucketUs), kBuckets - 1);
  buckets_[bucket].fetch_add(1, std::memory_order_relaxed);
  count_.fetch_add(1, std::memory_order_relaxed);
  auto seen = max_us_.load(std::memory_order_relaxed);
  while (us > seen && !max_us_.compare_exchange_weak(seen, us, std::memory_order_relaxed)) {
  }
}

std::int64_t LatenessHistogram::quantile_us(double q) const {
  const auto total = count();
  if (total == 0) return 0;
  const auto want = static_cast<std::uint64_t>(q * static_cast<double>(total));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < kBuckets; ++b) {
    seen += buckets_[b].load(std::memory_order_relaxed);
    if (seen > want) return static_cast<std::int64_t>(b + 1) * kBucketUs;
  }
  return max_us();
}

void ClassroomSeat::attach(const scenario::RunContext& context) {
  context.scheduler.set_lateness_observer(
      [this](sim::Duration late) { lateness_.add(std::chrono::duration_cast<std::chrono::microseconds>(late).count()); });
  plane_.attach(context);
}

}  // namespace control
