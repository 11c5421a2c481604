#include "engine/source_mark.h"

namespace scenario {

std::string SourceMark::to_string() const {
  const std::string f = file.empty() ? "<command line>" : file;
  if (line <= 0) return f;
  return f + ":" + std::to_string(line) + ":" + std::to_string(column);
}

}  // namespace scenario
