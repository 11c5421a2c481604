// The HTML report (`vplant run|test --report DIR`, docs/scenarios.md "The report"): a folder that
// opens from a downloaded CI artefact with no request leaving it:
//   DIR/index.html                 the suite table (case, result, simulated and wall time, speed)
//   DIR/cases/<case-id>/case.json  one case's summary: what the index is built from
//   DIR/cases/<case-id>/index.html the case page, its data inlined (no fetch: file:// forbids it)
//   DIR/assets/report.{js,css}     the page's code (dashboard/src/report/, embedded in vplant)
// Cases may be written by separate processes at once (`vplant test` runs each in its own); every
// file is written to a temporary name and renamed, so a reader never sees half a file.
#pragma once

#include <string>

#include "engine/reporting/html/case_record.h"

namespace scenario::report {

/// The case's folder name: `name` with every character outside [A-Za-z0-9._-] replaced by '_'
/// ("case" when nothing is left, "_" prefixed to a name of dots).
std::string case_id(const std::string& name);

/// Writes the case's summary, its page and the assets. Returns an error message, empty on success.
std::string write_case(const std::string& dir, const CaseRecord& record);

/// Reads every DIR/cases/*/case.json and writes DIR/index.html and the assets. A case.json that
/// cannot be read is listed as an error. Returns an error message, empty on success.
std::string write_index(const std::string& dir);

}  // namespace scenario::report
