// Current stage of one solenoid: the demand a (0..1 of the solenoid's side) becomes a current
// between Imin and Imax, with the DSP 408 dead-band compensation ("dvg dead band compensation":
// below the threshold the solenoid is off, at the threshold the current jumps to Imin).
//
//   a ≤ θ (or a = 0)  → 0 A                      (Imin when `imin_at_zero` and a = 0)
//   otherwise          → Imin + (Imax − Imin)·g(u),   u = (a − θ)/(1 − θ) if `rescale`, else a
//   falling curve      → Imax − (Imax − Imin)·g(u)  (inverted solenoid output)
//
// g is the identity or a characteristic curve (characteristic optimisation).
#pragma once

namespace dsp408 {

class CharacteristicCurve;

struct SolenoidCurve {
  double i_min = 0;   ///< A
  double i_max = 0;   ///< A
  double threshold = 0;  ///< dead band, fraction of the side's full scale (0..1)
  bool rescale = false;  ///< DSV: the range above the threshold is stretched to 0..1
  bool falling = false;  ///< inverted output
  bool imin_at_zero = false;  ///< "Imin always active": a = 0 gives Imin instead of 0
};

/// Current in A for demand `a` (clamped to 0..1). `curve` may be null (identity).
double solenoid_current(const SolenoidCurve& s, double a, const CharacteristicCurve* curve = nullptr);

}  // namespace dsp408
