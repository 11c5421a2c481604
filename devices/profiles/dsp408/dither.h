// Dither superimposed on a solenoid current: a square (or sine) wave of a given frequency whose
// peak-to-peak value is the amplitude (±A/2 around the DC current). The phase follows the
// simulation clock, so two runs produce the same samples.
#pragma once

#include <cstdint>

#include "sim/time.h"

namespace dsp408 {

class Dither {
 public:
  enum class Shape { Off, Square, Sine };

  /// Cheap when nothing changed (products configure it every control cycle).
  void configure(Shape shape, double frequency_hz, double amplitude_pp) {
    if (shape == shape_ && frequency_hz == frequency_ && amplitude_pp == amplitude_) return;
    shape_ = shape;
    frequency_ = frequency_hz;
    amplitude_ = amplitude_pp;
    milli_hz_ = milli_hz(frequency_hz);
  }
  /// Offset to add at time `t` (0 when off).
  double offset(sim::Time t) const;
  /// DC current plus dither, kept within [0, limit]; a current of 0 stays 0 (no dither on a
  /// switched-off solenoid).
  double apply(double dc, sim::Time t, double limit) const {
    if (dc <= 0) return 0;
    const double v = dc + offset(t);
    return v < 0.0 ? 0.0 : (limit < v ? limit : v);  // std::clamp(v, 0.0, limit)
  }

 private:
  static std::int64_t milli_hz(double frequency_hz);

  Shape shape_ = Shape::Off;
  double frequency_ = 0;
  double amplitude_ = 0;
  std::int64_t milli_hz_ = 0;  ///< the frequency in whole mHz (the phase is computed in them)
};

}  // namespace dsp408
