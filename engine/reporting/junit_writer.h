// JUnit XML of a run's verdicts: one testsuite (the scenario), one testcase per assertion, the
// failure message with the time, the expectation and the actual value; CI systems read it.
#pragma once

#include <string>

#include "engine/running/outcome.h"

namespace scenario {

/// Returns an error message, empty on success.
std::string write_junit(const std::string& path, const std::string& suite, const Verdicts& verdicts, double wall_seconds,
                        double simulated_seconds);

std::string xml_escape(const std::string& s);

}  // namespace scenario
