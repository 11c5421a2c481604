// Assertions that take time: a signal reaching a threshold within a window, holding a bound
// during a window (or until the end), rising at a slope; frames of an identifier counted, timed
// and checked for content during a window. They run beside the script, which does not wait for
// them; each is decided when its window closes (or the run ends) and recorded in Verdicts.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/can_frame.h"
#include "engine/running/outcome.h"
#include "engine/loading/scenario.h"
#include "engine/running/signal_source.h"

namespace scenario {

class AssertionMonitor {
 public:
  explicit AssertionMonitor(Verdicts& verdicts) : verdicts_(verdicts) {}

  /// Starts (or, for Mode::Now, decides at once) a signal expectation.
  void expect(const ExpectStep& e, Signal signal, const std::string& name, const SourceMark& mark, sim::Time now);
  void expect_frames(const ExpectFramesStep& e, int bus, const std::string& name, const SourceMark& mark, sim::Time now);

  void on_frame(int bus, const sim::CanFrame& f, sim::Time now);
  /// Samples the signals at `now` and decides what is due.
  void step(sim::Time now);
  /// The run ended at `end`: decides everything still open.
  void finish(sim::Time end);
  /// True while an expectation with a finite window is open (the run waits for it).
  bool pending() const;

 private:
  struct SignalWatch {
    ExpectStep spec;
    Signal signal;
    std::string name;
    SourceMark mark;
    sim::Time start{}, end{};
    double first = 0, last = 0, extreme = 0;
    bool seen = false;
    bool done = false;
  };
  struct FrameWatch {
    ExpectFramesStep spec;
    int bus = 0;
    std::string name;
    SourceMark mark;
    sim::Time start{}, end{};
    std::uint64_t count = 0;
    sim::Time last_time{};
    std::string violation;  ///< first content or period violation
    sim::Time violation_time{};
    bool done = false;
  };
  void decide(SignalWatch& w, sim::Time now, bool at_end);
  void decide(FrameWatch& w, sim::Time now);

  Verdicts& verdicts_;
  std::vector<SignalWatch> signals_;
  std::vector<FrameWatch> frames_;
};

}  // namespace scenario
