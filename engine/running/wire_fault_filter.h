// Wire faults on one bus (a sim::FrameFilter): frames matching a rule are dropped, delayed or
// corrupted as they are sent, or a node's transmission attempts are destroyed by bit errors
// (tx_errors), optionally with a probability and up to a count. Rules are added
// and removed by the fault injector; no allocation per frame.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/bus.h"
#include "engine/running/random.h"
#include "engine/loading/scenario.h"

namespace scenario {

class WireFaultFilter final : public sim::FrameFilter {
 public:
  explicit WireFaultFilter(Random* random) : random_(random) {}

  /// Activates a rule; returns its handle for remove().
  int add(const WireFault& fault);
  /// Frees the rule (a handle already removed, or whose count ran out, is ignored).
  void remove(int handle);
  /// Rules still in force: a removed rule, or one whose count ran out, is freed, so the cost per
  /// frame depends on these only, never on the rules a long run has ended.
  std::size_t active() const;

  Verdict on_send(sim::CanFrame& frame, int from_endpoint, sim::Time now) override;
  /// tx_errors rules: a bit error destroys this transmission attempt of the rule's node.
  bool on_transmit(const sim::CanFrame& frame, int from_endpoint, sim::Time start) override;

 private:
  struct Rule {
    WireFault fault;
    int handle = 0;
    std::uint64_t affected = 0;
    bool spent() const { return fault.count != 0 && affected >= fault.count; }
  };
  void free_spent();

  std::vector<Rule> rules_;  ///< in force, in the order they were added (the order they apply in)
  int next_handle_ = 0;
  bool spent_ = false;  ///< a rule's count ran out: freed at the next frame
  Random* random_;
};

}  // namespace scenario
