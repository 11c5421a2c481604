#include "devices/canopen/value_scaling.h"

#include <cmath>
#include <cstdio>

namespace canopen {

int decimals_for(double step) {
  step = std::fabs(step);
  int d = 0;
  // The smallest d for which one step shows as a non-zero number (0.0061 % → 0.006, 4 digits would
  // be noise: the step's first significant digit is enough).
  while (d < 6 && step > 0 && step * std::pow(10.0, d) < 0.95) ++d;
  return d;
}

ValueScaling scaled(std::string_view unit, double scale, double offset) {
  return ValueScaling{unit, scale, offset, decimals_for(scale)};
}

std::string scaled_text(double raw, const ValueScaling& s) {
  if (!s) return {};
  char buf[64];
  double v = s.apply(raw);
  if (v == 0) v = 0;  // no "-0.0"
  std::snprintf(buf, sizeof buf, "%.*f", s.decimals, v);
  std::string out = buf;
  if (out.size() > 1 && out[0] == '-' && out.find_first_not_of("-0.") == std::string::npos) out.erase(0, 1);
  if (s.unit != "°") out += " ";
  out += s.unit;
  return out;
}

}  // namespace canopen
