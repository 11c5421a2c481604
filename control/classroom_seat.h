// One seat of a classroom (`vplant classroom`, docs/classroom.md): a whole single-plant control
// plane, hosted by the classroom's server under /seats/K/, plus the lateness of its ticks in real
// time (the trainer's overview shows whether the machine keeps up with every seat).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

#include "control/control_plane.h"

namespace control {

/// Real-time tick lateness as a fixed histogram: written by the scheduler's thread without
/// allocating or locking, read by any thread.
class LatenessHistogram {
 public:
  static constexpr std::int64_t kBucketUs = 10;
  static constexpr std::size_t kBuckets = 2000;  ///< 0..20 ms; later ticks count in the last bucket

  void add(std::int64_t lateness_us);
  std::uint64_t count() const { return count_.load(std::memory_order_relaxed); }
  std::int64_t max_us() const { return max_us_.load(std::memory_order_relaxed); }
  /// The lateness `q` (0..1) of the ticks are below (bucket resolution); 0 with no ticks.
  std::int64_t quantile_us(double q) const;

 private:
  std::array<std::atomic<std::uint64_t>, kBuckets> buckets_{};
  std::atomic<std::uint64_t> count_{0};
  std::atomic<std::int64_t> max_us_{0};
};

class ClassroomSeat final : public scenario::RunExtension {
 public:
  explicit ClassroomSeat(UiOptions options) : plane_(std::move(options)) {}

  ControlPlane& plane() { return plane_; }
  const LatenessHistogram& lateness() const { return lateness_; }

  void attach(const scenario::RunContext& context) override;
  bool before_tick(bool end_reached) override { return plane_.before_tick(end_reached); }
  void detach() override { plane_.detach(); }
  /// POST /seats/K/api/restart: the runner rebuilds this seat at t = 0 and attaches again.
  bool wants_restart() override { return plane_.wants_restart(); }

 private:
  ControlPlane plane_;
  LatenessHistogram lateness_;
};

}  // namespace control
