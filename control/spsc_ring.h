// A bounded single-producer single-consumer queue without locks or allocation after
// construction: the scheduler's thread writes (and never waits: a full ring refuses), one server
// thread pops. Used for captured frames and signal samples.
//
// The producer writes into its own slots with plain stores and makes them visible in bulk with
// publish() (once per tick), so a captured frame costs a copy and no atomic operation, and the
// two threads share a cache line only once per tick rather than once per frame.
#pragma once

#include <atomic>
#include <cstddef>
#include <vector>

namespace control {

template <typename T>
class SpscRing {
 public:
  /// `capacity` is rounded up to a power of two.
  explicit SpscRing(std::size_t capacity, const T& prototype = T{})
      : slots_(round_up(capacity), prototype), mask_(slots_.size() - 1) {}

  // ---- producer ---------------------------------------------------------------------------------
  /// The slot the next commit() fills (fill it in place), or nullptr when the ring is full as of
  /// the last publish() (the caller counts what it dropped).
  T* claim() {
    if (write_ - tail_seen_ >= slots_.size()) return nullptr;
    return &slots_[write_ & mask_];
  }
  void commit() { ++write_; }
  /// Makes what was committed visible to the consumer and learns what it has taken since.
  void publish() {
    head_.store(write_, std::memory_order_release);
    tail_seen_ = tail_.load(std::memory_order_acquire);
  }
  /// Committed and not yet published.
  bool unpublished() const { return write_ != head_.load(std::memory_order_relaxed); }

  // ---- consumer ---------------------------------------------------------------------------------
  /// False when nothing published is left.
  bool pop(T& out) {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_seen_) {
      head_seen_ = head_.load(std::memory_order_acquire);
      if (tail == head_seen_) return false;
    }
    out = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return true;
  }
  std::size_t capacity() const { return slots_.size(); }

 private:
  static std::size_t round_up(std::size_t n) {
    std::size_t c = 2;
    while (c < n) c <<= 1;
    return c;
  }
  std::vector<T> slots_;
  std::size_t mask_;
  // Producer's own (plain: only its thread touches them).
  alignas(64) std::size_t write_ = 0;
  std::size_t tail_seen_ = 0;
  // Shared: written by one side each.
  alignas(64) std::atomic<std::size_t> head_{0};
  alignas(64) std::atomic<std::size_t> tail_{0};
  // Consumer's own.
  alignas(64) std::size_t head_seen_ = 0;
};

}  // namespace control
