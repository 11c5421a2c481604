#include "devices/profiles/dsp408/solenoid_current.h"

#include <algorithm>

#include "devices/profiles/dsp408/characteristic_curve.h"

namespace dsp408 {

double solenoid_current(const SolenoidCurve& s, double a, const CharacteristicCurve* curve) {
  a = std::clamp(a, 0.0, 1.0);
  if (a == 0) return s.imin_at_zero ? (s.falling ? s.i_max : s.i_min) : 0.0;
  if (a <= s.threshold) return 0.0;
  double u = a;
  if (s.rescale && s.threshold < 1) u = (a - s.threshold) / (1 - s.threshold);
  const double g = curve ? curve->map(u) : u;
  const double span = s.i_max - s.i_min;
  return s.falling ? s.i_max - span * g : s.i_min + span * g;
}

}  // namespace dsp408
