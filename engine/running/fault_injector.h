// Fault injection: applies a fault (wire, bus-off, device, power, plant parameter) now, schedules
// its end when it has a duration, and fires the scenario's `faults:` at their time or on their
// condition. Runs first in every tick, so everything else in the tick sees the fault.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sim/scheduler.h"
#include "engine/running/outcome.h"
#include "engine/loading/scenario.h"
#include "engine/running/wire_fault_filter.h"
#include "engine/running/world.h"

namespace scenario {

class FaultInjector final : public sim::Steppable {
 public:
  using Log = std::function<void(sim::Time, const std::string&)>;

  /// Checks every fault of the scenario against the world (nodes, fault names, plant parameters,
  /// signals of conditions); throws LoadError. Installs a WireFaultFilter on every bus.
  FaultInjector(World& world, Verdicts& verdicts, Log log);

  /// Validates one fault (also used for the script's fault steps); throws LoadError.
  void check(const FaultSpec& f);
  /// Applies `f` now (and schedules its end if it has a duration).
  void apply(const FaultSpec& f, sim::Time now);
  /// What undoes a fault applied by inject() (call it between ticks); empty when the fault has
  /// nothing to undo (power on, reset, a power cycle).
  using Clear = std::function<void(sim::Time)>;
  /// A fault injected into a running plant: what ends it early (empty when nothing to undo; safe
  /// to call after it ended) and, for a fault its target can end by itself, whether it has (a
  /// power-off is over once its node has power again, by any path: power on, reset, cycle).
  struct Injected {
    Clear clear;
    std::function<bool()> over;  ///< empty: over only through `clear` or its `for:`
  };
  /// A fault injected into a running plant (the HTTP API, the library): checks `f` and applies
  /// it now. A device fault or plant value that its target refuses throws LoadError at f.mark
  /// and changes nothing (a scenario's own faults fail a verdict instead). With `for:` the
  /// injector also ends it then.
  Injected inject(const FaultSpec& f, sim::Time now);

  void step(sim::Time now, sim::Duration dt) override;
  std::size_t applied() const { return applied_; }

 private:
  struct Scheduled {
    const FaultSpec* spec;
    Signal when;  ///< valid when spec->when
    bool fired = false;
  };
  struct Undo {
    sim::Time due;
    std::function<void(sim::Time)> action;
  };
  NodeInstance& node(const std::string& name);
  /// `refused`: null for a scenario's fault (a refusal fails a verdict), else where a refusal is
  /// told (and nothing is logged or counted).
  Clear apply_now(const FaultSpec& f, sim::Time now, std::string* refused);

  World& world_;
  Verdicts& verdicts_;
  Log log_;
  std::vector<std::unique_ptr<WireFaultFilter>> filters_;
  std::vector<Scheduled> scheduled_;
  std::vector<Undo> undo_;
  std::size_t applied_ = 0;
};

}  // namespace scenario
