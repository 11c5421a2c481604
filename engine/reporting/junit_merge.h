// One JUnit file from many: `vplant test --junit` merges the file each case's `vplant run --junit`
// wrote, element for element, so every <testcase> a run writes (assertions, and whatever else a
// run adds to its suite) appears in the merged file unchanged.
#pragma once

#include <string>
#include <vector>

namespace scenario {

/// The <testsuite> elements of a JUnit document, each verbatim.
std::vector<std::string> junit_testsuites(const std::string& xml);

/// A <testsuite> for a case that wrote no JUnit of its own (it crashed, timed out or could not
/// load): one testcase `run` with an <error> holding `message` and the case's output.
std::string junit_error_suite(const std::string& name, const std::string& message, const std::string& output,
                              double wall_seconds);

/// Writes <testsuites> with the summed counts (tests, failures, errors, time) around the
/// suites. Returns an error message, empty on success.
std::string write_merged_junit(const std::string& path, const std::vector<std::string>& testsuites);

}  // namespace scenario
