// The verdicts of a run: one Outcome per assertion (an expect, an SDO check, a wait with a
// timeout, a frame expectation), in the order they were decided.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "sim/time.h"
#include "engine/loading/source_mark.h"

namespace scenario {

struct Outcome {
  std::string name;
  SourceMark mark;
  bool passed = false;
  sim::Time time{};      ///< when it was decided
  std::string expected;  ///< failures: what should have been
  std::string actual;    ///< failures: what was
};

class Verdicts {
 public:
  void pass(std::string name, const SourceMark& mark, sim::Time t) {
    outcomes_.push_back(Outcome{std::move(name), mark, true, t, {}, {}});
  }
  void fail(std::string name, const SourceMark& mark, sim::Time t, std::string expected, std::string actual) {
    outcomes_.push_back(Outcome{std::move(name), mark, false, t, std::move(expected), std::move(actual)});
    ++failures_;
  }
  const std::vector<Outcome>& outcomes() const { return outcomes_; }
  std::size_t failures() const { return failures_; }

 private:
  std::vector<Outcome> outcomes_;
  std::size_t failures_ = 0;
};

}  // namespace scenario
