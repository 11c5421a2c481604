// The WDGA's position filter (2105h:01, manual §8.8): a first-order IIR on the unwrapped scaled
// count, y ← y + (S − y) / c with c = 1 (off) … 4, in fixed point so that c = 1 is exact.
#pragma once

#include <cstdint>

#include "devices/profiles/cia406/arithmetic.h"

namespace wdga {

class PositionFilter {
 public:
  void reset(cia406::Int128 s) { y_ = s * kOne; }
  /// One internal cycle; returns the filtered count (rounded).
  cia406::Int128 update(cia406::Int128 s, unsigned constant);

 private:
  static constexpr int kFractionBits = 16;  // fixed point: 16 fractional bits
  static constexpr std::int64_t kOne = std::int64_t{1} << kFractionBits;
  cia406::Int128 y_ = 0;
};

}  // namespace wdga
