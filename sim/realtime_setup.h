// Real-time scheduling for the thread that runs the scheduler (`vplant run --rt`, `vplant node
// --rt`): SCHED_FIFO at kRealtimePriority and all memory locked, where the process is allowed
// to. Where it is not, the run goes on with normal scheduling and the result says what is needed.
#pragma once

#include <string>

namespace sim {

/// SCHED_FIFO priority of the scheduler's thread: just below the threaded interrupt handlers of
/// a PREEMPT_RT kernel (50), so the CAN driver's interrupt thread still preempts the tick.
inline constexpr int kRealtimePriority = 49;

struct RealtimeSetup {
  bool fifo = false;    ///< the calling thread runs SCHED_FIFO at the priority asked for
  bool locked = false;  ///< mlockall(MCL_CURRENT | MCL_FUTURE) succeeded
  /// One line per part: what was set, or why not and what would allow it.
  std::string message;
};

/// Switches the *calling* thread to SCHED_FIFO at `priority` and locks the process's memory.
/// Call it on the scheduler's thread after the other threads are started (threads created later
/// by this thread inherit SCHED_FIFO). Never fails the run: a refusal is reported in the result.
RealtimeSetup enter_realtime(int priority = kRealtimePriority);

}  // namespace sim
