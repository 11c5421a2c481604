// A condition on one signal: above / below a threshold, inside or outside a band, or near a value
// within a tolerance. Used by waits, expectations and conditional faults. NaN never satisfies it.
#pragma once

#include <string>

#include "engine/loading/signal_expression.h"

namespace scenario {

struct Condition {
  enum class Op { Above, Below, Between, Outside, Near } op = Op::Above;
  SignalExpr signal;
  double a = 0;  ///< threshold, lower bound, or value (Near)
  double b = 0;  ///< upper bound, or tolerance (Near)

  bool holds(double v) const {
    switch (op) {
      case Op::Above: return v > a;
      case Op::Below: return v < a;
      case Op::Between: return v >= a && v <= b;
      case Op::Outside: return v < a || v > b;
      case Op::Near: return v >= a - b && v <= a + b;
    }
    return false;
  }
  /// "cyl.position > 0.2", "cyl.position = 0.1 ± 0.001".
  std::string describe() const;
};

/// Formats a value for messages (%.6g).
std::string format_value(double v);

}  // namespace scenario
