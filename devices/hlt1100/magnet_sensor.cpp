#include "devices/hlt1100/magnet_sensor.h"

#include <cmath>

#include "devices/profiles/cia406/arithmetic.h"

namespace hlt1100 {

Measurement measure(const MagnetInputs& in, const cia406::LinearConfig& config) {
  const double length_m = static_cast<double>(config.steps) * static_cast<double>(config.step_nm) * 1e-9;
  auto in_range = [length_m](double x) { return x >= 0.0 && x < length_m; };
  int magnets = static_cast<int>(cia406::llround_half_away(std::isfinite(in.magnet_count) ? in.magnet_count : 0.0));
  if (in.fault_magnet_lost) magnets = 0;
  int inside = 0;
  double seen = 0.0;
  if (magnets >= 1 && in_range(in.position) && !in.fault_out_of_range) {
    ++inside;
    seen = in.position;
  }
  if (magnets >= 2 && in_range(in.position2)) {
    ++inside;
    seen = in.position2;
  }
  if (in.fault_second_magnet && inside == 1) ++inside;
  if (inside != 1) return {};
  return Measurement{true, cia406::steps_from_metres(seen, config), cia406::llround_half_away(seen * 1e6)};
}

}  // namespace hlt1100
