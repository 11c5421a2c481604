// The scripted master: an endpoint on each bus that runs the scenario's script step by step
// (NMT, SYNC production, SDO transfers, PDOs and raw frames, waits) and starts the assertions.
// It sees every frame on its buses through a tap (its own included), so waits and frame
// expectations observe exactly what crossed the wire.
//
// Each tick (it runs after the fault injector and before the devices): decide due assertions on
// the signals at `now`, check the SDO timeout, execute steps until one blocks (a wait, an SDO
// transfer, a step whose `at` is in the future; steps that complete immediately run back to back
// in the same tick), then produce the due SYNCs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "devices/canopen/data_type.h"
#include "sim/bus.h"
#include "sim/scheduler.h"
#include "engine/running/assertion_monitor.h"
#include "engine/running/fault_injector.h"
#include "engine/running/outcome.h"
#include "engine/running/sdo_client.h"
#include "engine/running/sync_producer.h"
#include "engine/running/world.h"

namespace scenario {

class ScriptedMaster final : public sim::Steppable {
 public:
  using Log = std::function<void(sim::Time, const std::string&)>;

  /// Binds every step to the world (nodes, buses, signals, object types, values); throws LoadError.
  ScriptedMaster(World& world, FaultInjector& faults, Verdicts& verdicts, Log log);
  ~ScriptedMaster() override;

  void step(sim::Time now, sim::Duration dt) override;
  /// Every step has run and no assertion window is open.
  bool finished() const { return pc_ >= steps_.size() && !monitor_.pending(); }
  bool has_script() const { return !steps_.empty(); }
  /// The run ended at `end`: a step still pending and the open assertions are decided.
  void finish(sim::Time end);
  std::uint64_t frames_sent() const { return frames_sent_; }

 private:
  struct Endpoint;
  struct Bound {
    const Step* step = nullptr;
    std::string name;
    int bus = 0;
    std::uint8_t node_id = 0;
    NodeInstance* node = nullptr;
    bool typed = false;
    canopen::DataType type = canopen::DataType::Unsigned32;
    std::vector<std::uint8_t> bytes;  ///< SDO write data
    std::vector<Signal> signals;      ///< condition / expectation signal
  };

  void bind(Bound& b);
  void on_frame(int bus, const sim::CanFrame& f, sim::Time now);
  void send(int bus, const sim::CanFrame& f, sim::Time now);
  /// Starts step `b`; returns true when it is already complete.
  bool start(Bound& b, sim::Time now);
  /// Polls the running step; returns true when it is complete.
  bool poll(Bound& b, sim::Time now);
  bool send_rpdo(Bound& b, const RpdoStep& s, sim::Time now);
  void finish_sdo(Bound& b, sim::Time now);

  World& world_;
  FaultInjector& faults_;
  Verdicts& verdicts_;
  Log log_;
  AssertionMonitor monitor_;
  std::vector<std::unique_ptr<Endpoint>> endpoints_;
  std::vector<SyncProducer> sync_;
  std::vector<Bound> steps_;
  std::size_t pc_ = 0;
  bool started_ = false;
  sim::Time started_at_{};
  bool frame_matched_ = false;
  SdoClient sdo_;
  int sdo_bus_ = 0;
  sim::Time now_{};
  std::uint64_t frames_sent_ = 0;
};

}  // namespace scenario
