// A hook into a run for something that watches and steers it from outside the scenario (the
// live control plane, control/): the runner calls it on the scheduler's thread between ticks, so
// whatever it changes, it changes at a tick boundary. The engine knows nothing of HTTP.
#pragma once

namespace sim {
class Scheduler;
}

namespace scenario {

struct Scenario;
class World;
class FaultInjector;
class MasterMonitor;

struct RunContext {
  const Scenario& scenario;
  World& world;
  FaultInjector& faults;
  sim::Scheduler& scheduler;
  const MasterMonitor* master_monitor = nullptr;  ///< the verdict on the master (findings)
};

class RunExtension {
 public:
  virtual ~RunExtension() = default;
  /// Once, after everything is built and before the nodes power on.
  virtual void attach(const RunContext& context) = 0;
  /// Before every tick. `end_reached`: the duration or the script says the run is over. Returns
  /// false to end the run now; may hold the thread while the (virtual) clock is paused.
  virtual bool before_tick(bool end_reached) = 0;
  /// After the last tick (the outputs are not written yet).
  virtual void detach() = 0;
  /// Asked when before_tick returned false: true to start the run again at t = 0 (the runner
  /// rebuilds everything from the scenario, restarts its outputs and calls attach again, without
  /// detach).
  virtual bool wants_restart() { return false; }
};

}  // namespace scenario
