// Runs scenario text in the test environment, quietly, and returns the verdicts.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "tests/engine/test_world.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"

namespace vtest {

struct RunResult {
  int rc = -1;
  std::vector<scenario::Outcome> outcomes;
  scenario::RunSummary summary;
  std::string output;  ///< what the runner printed

  std::size_t failures() const {
    std::size_t n = 0;
    for (const auto& o : outcomes) n += !o.passed;
    return n;
  }
  /// "name: expected X, actual Y" of each failure, for test messages.
  std::string failure_text() const {
    std::string s;
    for (const auto& o : outcomes)
      if (!o.passed) s += o.mark.to_string() + ": " + o.name + ": expected " + o.expected + ", actual " + o.actual + "\n";
    return s;
  }
};

inline RunResult run_text(const std::string& yaml, scenario::RunOptions options = {}) {
  RunResult r;
  std::FILE* out = std::tmpfile();
  options.out = out;
  const auto s = scenario::parse_scenario(yaml, "test.yaml", ".");
  {
    scenario::Runner runner(s, test_environment(), options);
    r.rc = runner.run();
    r.outcomes = runner.verdicts().outcomes();
    r.summary = runner.summary();
  }
  std::rewind(out);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, out)) > 0) r.output.append(buf, n);
  std::fclose(out);
  return r;
}

}  // namespace vtest
