// Gathers a case for the HTML report while the runner runs it: adds the report's signals to the
// recorder (the scenario's `plots:`, else its CSV signals or every wired port, and each bus's
// load), taps the buses (FrameCapture), keeps the run's events (faults, script log lines), and
// after the run turns it all into a CaseRecord, decoding the kept frames.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/reporting/recorder.h"
#include "engine/reporting/html/case_record.h"
#include "engine/reporting/html/frame_capture.h"
#include "engine/running/run_summary.h"
#include "engine/running/world.h"

namespace scenario::report {

class CaseCollector {
 public:
  /// At most this many events (faults, log lines) and assertions are kept.
  static constexpr std::size_t kMaxEvents = 1000;
  static constexpr std::size_t kMaxOutcomes = 2000;
  /// Without `plots:`, at most this many signals get a plot each.
  static constexpr std::size_t kMaxDefaultSignals = 12;

  /// Call after the CSV's signals were added to `recorder` (the CSV's columns stay as they were).
  CaseCollector(const Scenario& scenario, World& world, Recorder& recorder);

  /// A line of the run's log at `t`; "fault: ..." lines are the faults injected.
  void event(sim::Time t, const std::string& text);

  CaseRecord finish(const Verdicts& verdicts, const RunSummary& summary, std::uint64_t seed, int exit_code) const;

 private:
  const Scenario& scenario_;
  World& world_;
  Recorder& recorder_;
  FrameCapture capture_;
  std::vector<std::string> signals_;
  std::vector<int> columns_;  // recorder column per signal
  std::vector<CaseRecord::Plot> plots_;
  std::vector<CaseRecord::Event> events_;
  std::size_t events_left_out_ = 0;

  int add_signal(const SignalExpr& e);
};

}  // namespace scenario::report
