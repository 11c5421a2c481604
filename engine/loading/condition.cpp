#include "engine/loading/condition.h"

#include <cstdio>

namespace scenario {

std::string format_value(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string Condition::describe() const {
  const std::string& s = signal.text;
  switch (op) {
    case Op::Above: return s + " > " + format_value(a);
    case Op::Below: return s + " < " + format_value(a);
    case Op::Between: return s + " in [" + format_value(a) + ", " + format_value(b) + "]";
    case Op::Outside: return s + " outside [" + format_value(a) + ", " + format_value(b) + "]";
    case Op::Near: return s + " = " + format_value(a) + " ± " + format_value(b);
  }
  return s;
}

}  // namespace scenario
