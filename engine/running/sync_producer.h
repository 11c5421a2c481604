// A SYNC producer on one bus (CiA 301 1005h/1006h/1019h as a master runs it): the period, the
// next due time and the optional counter byte. The scripted master's `sync` step and the control
// plane's POST /api/sync both drive one; no allocation, no I/O.
#pragma once

#include <cstdint>
#include <optional>

#include "sim/can_frame.h"
#include "sim/time.h"

namespace scenario {

struct SyncProducer {
  sim::Duration period{0};  ///< 0 = off
  sim::Time next{};
  std::uint8_t overflow = 0;  ///< 0 = no counter byte; 2..240 = the counter wraps after it
  std::uint8_t counter = 1;

  /// Starts (or with period 0 stops) producing: the first SYNC is due at `now`.
  void start(sim::Duration every, std::uint8_t counter_overflow, sim::Time now) {
    period = every;
    next = now;
    overflow = counter_overflow;
    counter = 1;
  }
  /// The SYNC due at `now`, if any (then the next one is scheduled; a period shorter than the
  /// tick gives one per tick).
  std::optional<sim::CanFrame> due(sim::Time now) {
    if (period.count() == 0 || now < next) return std::nullopt;
    sim::CanFrame f;
    f.id = 0x080;
    if (overflow) {
      f.dlc = 1;
      f.data[0] = counter;
      counter = counter >= overflow ? 1 : static_cast<std::uint8_t>(counter + 1);
    }
    next += period;
    if (next <= now) next = now + period;
    return f;
  }
};

}  // namespace scenario
