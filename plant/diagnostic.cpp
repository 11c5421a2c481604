#include "plant/diagnostic.h"

#include <fmt/format.h>

namespace plant {

std::string Diagnostic::to_string() const {
  if (mark.line > 0) return fmt::format("{}:{}:{}: {}", mark.file, mark.line, mark.column, reason);
  if (!mark.file.empty()) return fmt::format("{}: {}", mark.file, reason);
  return reason;
}

}  // namespace plant
