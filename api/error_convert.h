// Private to the library: the one place the project's diagnostic (sim/diagnostic.h) becomes the
// public vplant::Error, so a scenario, signal or fault the library rejects reads as `vplant run`
// prints it.
#pragma once

#include <vplant/error.h>

#include <string>

#include "sim/diagnostic.h"

namespace vplant::detail {

inline Error to_error(const sim::Diagnostic& d) {
  return Error(d.mark.file, d.mark.line, d.mark.column, d.reason, d.to_string());
}

/// A refusal of a call that names no file: the reason alone.
[[noreturn]] inline void fail(const std::string& reason) { throw to_error(sim::Diagnostic{{}, reason}); }

}  // namespace vplant::detail
