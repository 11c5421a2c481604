// Where a piece of a scenario was written, and the error that points there. Every rejection of a
// scenario file (syntax, unknown key, bad value, missing port, ...) is a LoadError whose text is
// `file:line:col: reason`, which `vplant run` prints before exiting with 2.
#pragma once

#include <stdexcept>
#include <string>

#include "sim/source_mark.h"

namespace scenario {

/// The project's one source mark (sim/source_mark.h).
using sim::SourceMark;

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
