// A CANopen slave node: object dictionary + the CiA 301 services + optional LSS slave, attached
// to one bus. Received frames are dispatched through a COB-ID table (O(1), no allocation); time
// advances through step(). A product is a Node plus an Application (its behaviour).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "devices/canopen/application.h"
#include "devices/canopen/nmt_state.h"
#include "devices/canopen/node_policy.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/service_links.h"
#include "devices/transition_log.h"
#include "sim/bus.h"
#include "sim/scheduler.h"

namespace canopen {

class Emergency;
class SdoServer;
class NmtSlave;
class ErrorControl;
class HeartbeatConsumer;
class SyncConsumer;
class PdoService;
class StoreRestore;
class LssSlave;
struct LssPolicy;

/// The composition root of the services: it builds each one with the pieces it needs and, through
/// the service_links.h interfaces it implements, passes their events on (see node.cpp).
class Node final : public sim::FrameReceiver,
                   public sim::Steppable,
                   private FrameSender,
                   private RoutesChanged,
                   private EmcyRequests,
                   private NmtCommandHandler,
                   private SyncEvents,
                   private PdoEvents,
                   private CommErrorEvents,
                   private SilenceRequest,
                   private LssEvents {
 public:
  static constexpr std::uint8_t kUnconfigured = kUnconfiguredNodeId;

  Node(std::string name, ObjectDictionary od, NodePolicy policy, std::uint8_t node_id);
  ~Node() override;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  void set_application(Application* app) { app_ = app; }
  /// Where the NMT state machine records its transitions (the Device's log); nullptr = nowhere.
  void set_transition_log(devices::TransitionLog* log) { transitions_ = log; }
  devices::TransitionLog* transition_log() const { return transitions_; }
  Application& app() { return app_ ? *app_ : null_app_; }
  /// Adds an LSS slave (CiA 305). Identity comes from 0x1018.
  void enable_lss(const LssPolicy& policy);

  void attach(sim::Bus& bus);
  /// Power-on: reload stored parameters, reset application and communication, boot-up (after
  /// the policy's boot delay). `now` is the current simulation time.
  void power_on(sim::Time now);
  /// Power-off: silent, state lost except non-volatile storage.
  void power_off();
  bool powered() const { return powered_; }
  /// How many times the node was powered on: a power-off fault is over once this moves on.
  std::uint64_t power_ons() const { return power_ons_; }

  void on_frame(const sim::CanFrame& frame, sim::Time now) override;
  /// The bus's fault confinement (sim::Bus): error passive raises EMCY 8120h (or the product's
  /// reaction), bus-off silences the node, the recovery ends in communication_error(BusOffRecovered).
  void on_error_state(sim::ErrorState state, sim::Time now) override;
  void step(sim::Time now, sim::Duration dt) override;

  // --- state ----------------------------------------------------------------------------------
  const std::string& name() const { return name_; }
  ObjectDictionary& od() { return od_; }
  const ObjectDictionary& od() const { return od_; }
  NodePolicy& policy() { return policy_; }
  const NodePolicy& policy() const { return policy_; }
  std::uint8_t node_id() const { return status_.node_id; }
  /// The endpoint id on the attached bus (-1 before attach); for Bus::set_online (bus-off faults).
  int endpoint() const { return endpoint_; }
  std::uint8_t pending_node_id() const { return status_.pending_node_id; }
  /// Node-ID that the next communication reset applies (LSS, 0x2000-style objects).
  void set_pending_node_id(std::uint8_t id) override { status_.pending_node_id = id; }
  NmtState nmt_state() const { return status_.nmt_state; }
  sim::Time now() const { return status_.now; }

  Emergency& emergency() { return *emcy_; }
  SdoServer& sdo() { return *sdo_; }
  PdoService& pdo() { return *pdo_; }
  ErrorControl& error_control() { return *error_control_; }
  HeartbeatConsumer& heartbeat_consumer() { return *heartbeat_consumer_; }
  SyncConsumer& sync() { return *sync_; }
  StoreRestore& store() { return *store_; }
  LssSlave* lss() { return lss_.get(); }

  // --- actions --------------------------------------------------------------------------------
  /// Transmits a frame (dropped while powered off, silent or bus-off).
  void send(const sim::CanFrame& frame) override;
  /// Executes an NMT command as if received; `sender` names who sent it in the transition log.
  void execute_nmt(NmtCommand command, std::string_view sender = "the master") override;
  /// Changes the NMT state directly (e.g. error behaviour 0x1029 → Pre-operational).
  void set_nmt_state(NmtState state);
  /// Bus-off (CAN controller fault): no frame in or out, the device keeps running.
  void set_bus_off(bool off) {
    bus_off_ = off;
    refresh_rx_gate();
  }
  bool bus_off() const { return bus_off_; }
  /// Waiting for automatic bit-rate detection (LssPolicy::automatic_bit_rate_index).
  bool detecting_bit_rate() const { return detecting_bit_rate_; }
  /// The bit rate the node runs at in kbit/s: the LSS active rate, the detected rate, or 0
  /// when unknown (no LSS, or still detecting on a bus without a rate).
  unsigned bit_rate_kbit() const;
  /// No frame in or out until `until` (e.g. while "saving to EEPROM").
  void go_silent_until(sim::Time until) override { status_.silent_until = until; }
  bool silent() const { return status_.silent(); }
  /// The RPDO (1-based) that a frame with this identifier reaches, 0 = none: lets a monitor of
  /// the master check an RPDO's length against its mapping without a table of its own.
  int rpdo_for(std::uint32_t id, bool extended) const {
    const RouteEntry r = extended ? extended_route(id) : id < routes_.size() ? routes_[id] : RouteEntry{};
    return r.route == Route::Rpdo ? r.index : 0;
  }
  /// Re-reads COB-IDs from the object dictionary into the dispatch table.
  void rebuild_dispatch() override;
  /// A communication error (life guarding, heartbeat consumer) began / ended: the application
  /// may handle it; otherwise EMCY per policy and the 0x1029:01 reaction.
  /// `evidence`: the heartbeat producer's node-ID, the guarding life time in ms (transition log).
  void communication_error(CommError error, std::uint32_t evidence = 0) override;
  void communication_recovered(CommError error) override;

  // --- transition log -------------------------------------------------------------------------
  /// Why the NMT state changes now: set by whoever starts a change (command, timeout, power) for
  /// as long as the change and its consequences run (CauseScope), read when a transition is
  /// recorded. A product's application reads it too (node().cause()): a DSP 408 TR_8 forced by
  /// NMT Stop names the Stop.
  struct NmtCause {
    devices::TransitionCause cause = devices::TransitionCause::Internal;
    std::uint32_t value = 0;
    std::string_view detail;
    std::string_view transition;
  };
  class CauseScope {
   public:
    CauseScope(Node& n, NmtCause c) : node_(n), saved_(n.cause_) { n.cause_ = c; }
    ~CauseScope() { node_.cause_ = saved_; }
    CauseScope(const CauseScope&) = delete;
    CauseScope& operator=(const CauseScope&) = delete;

   private:
    Node& node_;
    NmtCause saved_;
  };
  const NmtCause& cause() const { return cause_; }

  // Counters for diagnostics and tests.
  struct Stats {
    std::uint64_t rx_frames = 0;
    std::uint64_t tx_frames = 0;
    std::uint64_t ignored_frames = 0;
  };
  const Stats& stats() const { return stats_; }

 private:
  enum class Route : std::uint8_t { None, Nmt, Sync, Rpdo, TpdoRtr, SdoRx, ErrorControl, HeartbeatConsumer, Lss };
  struct RouteEntry {
    Route route = Route::None;
    std::uint8_t index = 0;
  };
  struct ExtendedRoute {
    std::uint32_t id;
    RouteEntry entry;
  };

  void add_route(std::uint32_t cob_id, Route r, std::uint8_t index = 0);
  RouteEntry extended_route(std::uint32_t id) const;
  void dispatch(RouteEntry route, const sim::CanFrame& frame, sim::Time now);
  void detect_bit_rate(sim::Time now);
  /// Recomputes rx_plain_; called wherever one of the flags it sums up changes.
  void refresh_rx_gate() {
    rx_plain_ = powered_ && !bus_off_ && !detecting_bit_rate_ && status_.node_id >= 1 && status_.node_id <= 127 && !boot_pending_;
  }
  // The services' events that only the node sees (service_links.h).
  void raise_emcy(std::uint16_t code) override;
  void clear_emcy(std::uint16_t code) override;
  void sync_received(std::uint8_t pdo_counter, std::uint8_t counter, sim::Time now) override;
  void rpdo_received(int number) override { app().on_rpdo(number); }
  void before_tpdo(int number) override { app().before_tpdo(number); }
  void apply_pending_node_id() override { reset_communication(); }

  void reset_application();
  void reset_communication();
  void send_boot_up();
  void record_nmt(std::string_view from, std::string_view to);
  /// The node may use the bus: it has no rate of its own to compare, or it matches the bus's.
  /// Inline: every frame in and out asks, and a bus without a rate answers at once.
  bool on_bus_rate() const { return !bus_ || bus_->bit_rate_kbit() == 0 || own_rate_matches_bus(); }
  bool own_rate_matches_bus() const;

  std::string name_;
  ObjectDictionary od_;
  NodePolicy policy_;
  /// Node-ID, NMT state, time, silence: read by the services by reference.
  NodeStatus status_;
  bool powered_ = false;
  bool boot_pending_ = false;
  sim::Time boot_due_{};
  bool bus_off_ = false;
  sim::ErrorState controller_state_ = sim::ErrorState::Active;
  bool detecting_bit_rate_ = false;
  /// Powered, not bus-off, not detecting the bit rate, configured and booted: a received frame
  /// needs only the time-dependent checks (silent, bit rate) before its route (on_frame()).
  bool rx_plain_ = false;
  unsigned detected_kbit_ = 0;

  sim::Bus* bus_ = nullptr;
  int endpoint_ = -1;
  Application* app_ = nullptr;
  Application null_app_;

  std::array<RouteEntry, 2048> routes_{};
  std::vector<ExtendedRoute> extended_routes_;

  std::unique_ptr<Emergency> emcy_;
  std::unique_ptr<SdoServer> sdo_;
  std::unique_ptr<NmtSlave> nmt_;
  std::unique_ptr<ErrorControl> error_control_;
  std::unique_ptr<HeartbeatConsumer> heartbeat_consumer_;
  std::unique_ptr<SyncConsumer> sync_;
  std::unique_ptr<PdoService> pdo_;
  std::unique_ptr<StoreRestore> store_;
  std::unique_ptr<LssSlave> lss_;
  Stats stats_;
  devices::TransitionLog* transitions_ = nullptr;
  NmtCause cause_;
  NmtCause boot_cause_;   ///< what started the pending boot-up (power, reset command)
  bool ever_powered_ = false;
  std::uint64_t power_ons_ = 0;
};

}  // namespace canopen
