// Where a piece of a scenario was written, and the error that points there. Every rejection of a
// scenario file (syntax, unknown key, bad value, missing port, ...) is a LoadError whose text is
// `file:line:col: reason`, which `vplant run` prints before exiting with 2.
#pragma once

#include <stdexcept>
#include <string>

namespace scenario {

/// 1-based line and column; 0 = not from a file (built in code, or a command-line override).
struct SourceMark {
  std::string file;
  int line = 0;
  int column = 0;

  /// "file:line:col" (or "file" / "<command line>" when the position is unknown).
  std::string to_string() const;
};

class LoadError : public std::runtime_error {
 public:
  LoadError(const SourceMark& mark, const std::string& reason)
      : std::runtime_error(mark.to_string() + ": " + reason), mark_(mark), reason_(reason) {}
  const SourceMark& mark() const { return mark_; }
  const std::string& reason() const { return reason_; }

 private:
  SourceMark mark_;
  std::string reason_;
};

}  // namespace scenario
