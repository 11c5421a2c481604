// Where a piece of a file was written: the project's one source mark, what a sim::Diagnostic
// (sim/diagnostic.h) points with. In sim/ because that is the lowest layer the plant, the EDS
// reader and the engine all stand on (plant/ is optional in a build).
#pragma once

#include <string>

namespace sim {

/// 1-based line and column; 0 = not from a file (built in code, or a command-line override).
struct SourceMark {
  std::string file;
  int line = 0;
  int column = 0;

  /// "file:line:col" ("file:line" without a column; "file" / "<command line>" without a line).
  std::string to_string() const;
};

}  // namespace sim
