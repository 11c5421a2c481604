// Wire faults on one bus (a sim::FrameFilter): frames matching a rule are dropped, delayed or
// corrupted as they are sent, or a node's transmission attempts are destroyed by bit errors
// (tx_errors), optionally with a probability and up to a count. Rules are added
// and removed by the fault injector; no allocation per frame.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/bus.h"
#include "engine/random.h"
#include "engine/scenario.h"

namespace scenario {

class WireFaultFilter final : public sim::FrameFilter {
 public:
  explicit WireFaultFilter(Random* random) : random_(random) {}

  /// Activates a rule; returns its handle for remove().
  int add(const WireFault& fault);
  void remove(int handle);
  std::uint64_t affected(int handle) const { return rules_[static_cast<std::size_t>(handle)].affected; }

  Verdict on_send(sim::CanFrame& frame, int from_endpoint, sim::Time now) override;
  /// tx_errors rules: a bit error destroys this transmission attempt of the rule's node.
  bool on_transmit(const sim::CanFrame& frame, int from_endpoint, sim::Time start) override;

 private:
  struct Rule {
    WireFault fault;
    bool active = false;
    std::uint64_t affected = 0;
  };
  std::vector<Rule> rules_;
  Random* random_;
};

}  // namespace scenario
