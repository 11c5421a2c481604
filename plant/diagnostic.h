// How the plant reports a rejected description (the project's one diagnostic, sim/diagnostic.h)
// or a refused run-time change (Status).
#pragma once

#include <string>

#include "sim/diagnostic.h"

namespace plant {

/// Where a piece of a plant description was written (0: built in code): the project's one mark.
using sim::SourceMark;
/// A reason, printed as `file:line:col: reason` when the mark is known.
using sim::Diagnostic;
/// Thrown when a plant description cannot be built: the same class as scenario::LoadError, so the
/// engine lets it through unchanged (catching one catches the other).
using DescriptionError = sim::DiagnosticError;

/// Outcome of a run-time change (set_parameter): ok, or the reason it was refused.
class Status {
 public:
  static Status success() { return Status{}; }
  static Status failure(std::string reason) { return Status{std::move(reason)}; }

  bool ok() const { return reason_.empty(); }
  explicit operator bool() const { return ok(); }
  const std::string& reason() const { return reason_; }

 private:
  Status() = default;
  explicit Status(std::string reason) : reason_(reason.empty() ? "refused" : std::move(reason)) {}
  std::string reason_;
};

}  // namespace plant
