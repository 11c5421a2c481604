// The project's one diagnostic: a reason and where it was written. The plant's descriptions, the
// engine's scenarios, EDS files and the public API all report with it, printed as
// `file:line:col: reason`. In sim/ because that is the lowest layer all of them stand on.
#pragma once

#include <stdexcept>
#include <string>

#include "sim/source_mark.h"

namespace sim {

struct Diagnostic {
  SourceMark mark;
  std::string reason;
  /// A warning: the input was read (an EDS deviation a master tolerates), printed with "warning: ".
  bool warning = false;

  /// "file:line:col: reason" ("file:line: reason" without a column, "file: reason" without a
  /// line, the reason alone when it comes from no file); warnings read "...: warning: reason".
  std::string to_string() const;
};

/// Thrown for input that cannot be used (a plant description, a scenario, a request body);
/// what() is the formatted diagnostic. plant::DescriptionError and scenario::LoadError name it.
class DiagnosticError : public std::runtime_error {
 public:
  explicit DiagnosticError(Diagnostic d) : std::runtime_error(d.to_string()), diagnostic_(std::move(d)) {}
  DiagnosticError(SourceMark mark, std::string reason) : DiagnosticError(Diagnostic{std::move(mark), std::move(reason)}) {}

  const Diagnostic& diagnostic() const { return diagnostic_; }
  const SourceMark& mark() const { return diagnostic_.mark; }
  const std::string& reason() const { return diagnostic_.reason; }

 private:
  Diagnostic diagnostic_;
};

}  // namespace sim
