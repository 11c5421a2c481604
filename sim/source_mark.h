// Where a piece of a file was written: the project's one source mark, shared by the plant's
// descriptions (plant::Diagnostic) and the engine's scenarios (scenario::LoadError). In sim/
// because that is the lowest layer both stand on (plant/ is optional in a build).
#pragma once

#include <string>

namespace sim {

/// 1-based line and column; 0 = not from a file (built in code, or a command-line override).
struct SourceMark {
  std::string file;
  int line = 0;
  int column = 0;

  /// "file:line:col" (or "file" / "<command line>" when the position is unknown).
  std::string to_string() const;
};

}  // namespace sim
