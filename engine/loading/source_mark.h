// Where a piece of a scenario was written, and the error that points there. Every rejection of a
// scenario file (syntax, unknown key, bad value, missing port, ...) is a LoadError whose text is
// `file:line:col: reason`, which `vplant run` prints before exiting with 2.
#pragma once

#include "sim/diagnostic.h"

namespace scenario {

/// The project's one source mark (sim/source_mark.h).
using sim::SourceMark;
/// The engine's name for the project's one diagnostic exception (sim/diagnostic.h): a plant's
/// DescriptionError is the same class, so it reaches the CLI and the API without a converter.
using LoadError = sim::DiagnosticError;

}  // namespace scenario
