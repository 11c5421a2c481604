// How the plant reports a rejected description or parameter: a reason, and where it came from.
#pragma once

#include <stdexcept>
#include <string>

#include "sim/source_mark.h"

namespace plant {

/// Where a piece of a plant description was written (0: built in code): the project's one mark.
using sim::SourceMark;

/// A reason, printed as `file:line:col: reason` when the mark is known.
struct Diagnostic {
  SourceMark mark;
  std::string reason;

  std::string to_string() const;
};

/// Thrown when a plant description cannot be built; what() is the formatted diagnostic.
class DescriptionError : public std::runtime_error {
 public:
  explicit DescriptionError(Diagnostic d) : std::runtime_error(d.to_string()), diagnostic_(std::move(d)) {}
  const Diagnostic& diagnostic() const { return diagnostic_; }

 private:
  Diagnostic diagnostic_;
};

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
