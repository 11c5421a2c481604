// What the magnetostrictive waveguide sees: the magnets inside the measuring range (0 ≤ x < L
// from the start of the range at the sensor head). One magnet gives a position; none (magnet
// lost or outside the range) or two (a second magnet inside) is the position error of 6503h
// bit 0 — the device supports a single magnet only (6020h has one sub-index).
#pragma once

#include <cstdint>

#include "devices/profiles/cia406/linear_position.h"

namespace hlt1100 {

/// Plant inputs (SI units) and injected faults.
struct MagnetInputs {
  double position = 0.0;      ///< m, magnet 1
  double position2 = 0.0;     ///< m, magnet 2 (counts only with magnet_count = 2)
  double magnet_count = 1.0;  ///< magnets on the rod: 0, 1 or 2
  bool fault_magnet_lost = false;
  bool fault_second_magnet = false;
  bool fault_out_of_range = false;
};

struct Measurement {
  bool valid = false;
  std::int64_t steps = 0;        ///< along the rod, 0..N-1 (valid only)
  std::int64_t micrometres = 0;  ///< the waveguide's finer internal reading (speed is derived from it)
};

Measurement measure(const MagnetInputs& in, const cia406::LinearConfig& config);

}  // namespace hlt1100
