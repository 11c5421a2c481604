// A scripted signal for a sensor input when a node runs alone (`vplant node --device ...`
// without a plant): the input is held at its set value, or moves as a ramp or a sine around it.
//   "hold"            value(t) = base
//   "ramp:RATE"       value(t) = base + RATE·t            (RATE in input units per second)
//   "sine:AMP,FREQ"   value(t) = base + AMP·sin(2π·FREQ·t) (FREQ in Hz)
// t is simulation time, so a power cycle does not disturb the signal.
#pragma once

#include <string>
#include <string_view>

namespace cia406 {

class ScriptedInput {
 public:
  enum class Shape { Hold, Ramp, Sine };

  /// Parses the setting text; returns an error message, empty on success.
  std::string parse(std::string_view text);
  Shape shape() const { return shape_; }
  bool scripted() const { return shape_ != Shape::Hold; }
  /// Value and derivative at time t (seconds) around `base`.
  double value(double base, double t) const;
  double derivative(double t) const;

 private:
  Shape shape_ = Shape::Hold;
  double a_ = 0;  // ramp rate or sine amplitude
  double f_ = 0;  // sine frequency
};

}  // namespace cia406
