// Keeps a bounded sample of the frames a run put on its buses for the report's trace: the first
// kHead frames and a ring of the last kTail, so a long run's page stays small and still shows how
// it began and how it ended (where a failure usually is). Storage is allocated once; a frame costs
// a copy, never an allocation (it is a bus tap on the scheduler's thread).
#pragma once

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "sim/bus.h"

namespace scenario::report {

class FrameCapture {
 public:
  static constexpr std::size_t kHead = 1000;
  static constexpr std::size_t kTail = 1000;

  struct Captured {
    sim::Time time{};
    std::uint16_t bus = 0;  ///< index into the buses given to tap()
    sim::CanFrame frame;
  };

  FrameCapture();
  /// Taps every bus; a frame's `bus` is the bus's index in `buses`.
  void tap(const std::vector<std::unique_ptr<sim::Bus>>& buses);

  /// The kept frames in the order they crossed the buses.
  std::vector<Captured> frames() const;
  /// Every frame seen (kept or not).
  std::uint64_t seen() const { return seen_; }

 private:
  class BusTap final : public sim::FrameTap {
   public:
    BusTap(FrameCapture& capture, std::uint16_t bus) : capture_(capture), bus_(bus) {}
    void on_bus_frame(std::string_view, const sim::CanFrame& frame, sim::Time now) override {
      capture_.add(bus_, frame, now);
    }

   private:
    FrameCapture& capture_;
    std::uint16_t bus_;
  };
  void add(std::uint16_t bus, const sim::CanFrame& frame, sim::Time now);

  std::vector<std::unique_ptr<BusTap>> taps_;
  std::vector<Captured> head_, tail_;  // tail_: a ring once full
  std::uint64_t seen_ = 0;
};

}  // namespace scenario::report
