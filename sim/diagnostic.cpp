#include "sim/diagnostic.h"

namespace sim {

std::string Diagnostic::to_string() const {
  const std::string text = warning ? "warning: " + reason : reason;
  if (mark.file.empty() && mark.line <= 0) return text;
  return mark.to_string() + ": " + text;
}

}  // namespace sim
