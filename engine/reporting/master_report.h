// What a run makes of the master monitor's findings (after the run, off the scheduler's thread):
// the `--master-report` JSON file, one JUnit test case per rule, the lines of the run summary.
#pragma once

#include <cstdio>
#include <string>

#include "sim/time.h"
#include "engine/running/outcome.h"

namespace scenario {

class MasterMonitor;

/// Writes findings_json() to `path`; returns an error message, empty on success.
std::string write_master_report(const std::string& path, const MasterMonitor& monitor);
/// One outcome per rule that is not off, named "master rule <name>": failed when the rule is of
/// error severity and has findings (the first one is the actual value), passed otherwise.
void add_rule_outcomes(const MasterMonitor& monitor, const SourceMark& mark, sim::Time end, Verdicts& verdicts);
/// "  master findings: N (E errors, W warnings)" and the first findings, one a line; nothing when
/// there are none unless `always`.
void print_findings(std::FILE* out, const MasterMonitor& monitor, bool always);

}  // namespace scenario
