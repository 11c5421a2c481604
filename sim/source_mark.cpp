#include "sim/source_mark.h"

namespace sim {

std::string SourceMark::to_string() const {
  const std::string f = file.empty() ? "<command line>" : file;
  if (line <= 0) return f;
  if (column <= 0) return f + ":" + std::to_string(line);
  return f + ":" + std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace sim
