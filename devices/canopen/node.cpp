#include "devices/canopen/node.h"

#include "devices/canopen/emergency.h"
#include "devices/canopen/error_control.h"
#include "devices/canopen/heartbeat_consumer.h"
#include "devices/canopen/lss_slave.h"
#include "devices/canopen/nmt_slave.h"
#include "devices/canopen/pdo_service.h"
#include "devices/canopen/sdo_server.h"
#include "devices/canopen/store_restore.h"
#include "devices/canopen/sync_consumer.h"
#include "sim/log.h"

namespace canopen {

namespace {
constexpr std::uint16_t kErrorBehaviour = 0x1029;
constexpr std::uint32_t kLssMasterToSlave = 0x7E5;

using devices::TransitionCause;

/// The transition's name in the log and the machine description (nmt_machine.cpp).
std::string_view command_transition(NmtCommand c) {
  switch (c) {
    case NmtCommand::Start: return "NMT 01h";
    case NmtCommand::Stop: return "NMT 02h";
    case NmtCommand::EnterPreOperational: return "NMT 80h";
    case NmtCommand::ResetNode: return "NMT 81h";
    case NmtCommand::ResetCommunication: return "NMT 82h";
  }
  return "";
}
}  // namespace

// The composition root: each service gets only what it needs (the dictionary, its policy, the
// node's status, a frame sender) and reports its events through the interfaces this node
// implements (service_links.h), which pass them on to another service or the application.
Node::Node(std::string name, ObjectDictionary od, NodePolicy policy, std::uint8_t node_id)
    : name_(std::move(name)),
      od_(std::move(od)),
      policy_(std::move(policy)),
      status_{.node_id = node_id, .pending_node_id = node_id} {
  // The events each service raises, as the narrow interfaces it is given.
  FrameSender& sender = *this;
  RoutesChanged& routes = *this;
  EmcyRequests& emcy = *this;
  NmtCommandHandler& nmt_commands = *this;
  SyncEvents& sync_events = *this;
  PdoEvents& pdo_events = *this;
  CommErrorEvents& comm_errors = *this;
  SilenceRequest& silence = *this;
  emcy_ = std::make_unique<Emergency>(od_, policy_.emcy, status_, sender);
  sdo_ = std::make_unique<SdoServer>(od_, policy_.sdo, status_, sender);
  nmt_ = std::make_unique<NmtSlave>(policy_.nmt, status_, nmt_commands);
  error_control_ = std::make_unique<ErrorControl>(od_, policy_.error_control, status_, sender, comm_errors);
  heartbeat_consumer_ = std::make_unique<HeartbeatConsumer>(od_, policy_.error_control, comm_errors, routes);
  sync_ = std::make_unique<SyncConsumer>(od_, policy_.pdo, status_, sync_events, emcy, routes);
  pdo_ = std::make_unique<PdoService>(od_, policy_.pdo, status_, sender, pdo_events, emcy, routes);
  store_ = std::make_unique<StoreRestore>(od_, policy_.store, status_, name_, silence);
  emcy_->bind_objects();
  error_control_->bind_objects();
  heartbeat_consumer_->bind_objects();
  sync_->bind_objects();
  pdo_->bind_objects();
  store_->bind_objects();
}

Node::~Node() = default;

void Node::enable_lss(const LssPolicy& policy) {
  FrameSender& sender = *this;
  LssEvents& events = *this;
  SilenceRequest& silence = *this;
  lss_ = std::make_unique<LssSlave>(policy, od_, status_, store_->memory(), sender, events, silence);
}

void Node::attach(sim::Bus& bus) {
  bus_ = &bus;
  endpoint_ = bus.attach(this);
}

unsigned Node::bit_rate_kbit() const {
  if (!lss_) return 0;
  const auto& automatic = lss_->policy().automatic_bit_rate_index;
  if (automatic && lss_->active_bit_rate() == *automatic) return detected_kbit_;
  return lss_bit_rate_kbit(lss_->active_bit_rate());
}

bool Node::own_rate_matches_bus() const {
  const unsigned own = bit_rate_kbit();
  return own == 0 || own == bus_->bit_rate_kbit();
}

void Node::send(const sim::CanFrame& frame) {
  if (!powered_ || silent() || bus_off_ || detecting_bit_rate_ || !bus_ || !on_bus_rate()) return;
  ++stats_.tx_frames;
  bus_->send(endpoint_, frame, status_.now);
}

// ---- life cycle ---------------------------------------------------------------------------------

void Node::power_on(sim::Time now) {
  status_.now = now;
  powered_ = true;
  status_.silent_until = now;
  status_.nmt_state = NmtState::Initialising;
  // The first power-on is the boot; any later one a power cycle (scenario, page button).
  boot_cause_ = ever_powered_ ? NmtCause{TransitionCause::Power, 1, "", "power on"}
                              : NmtCause{TransitionCause::Boot, 0, "", "power on"};
  ever_powered_ = true;
  ++power_ons_;
  const CauseScope scope(*this, boot_cause_);
  record_nmt("OFF", "INITIALISING");
  std::string error;
  if (!store_->power_on(error)) sim::log(sim::LogLevel::Error, "node {}: {}; using defaults", name_, error);
  bus_off_ = false;
  detecting_bit_rate_ = false;
  detected_kbit_ = 0;
  if (lss_) {
    lss_->power_on();
    const auto& automatic = lss_->policy().automatic_bit_rate_index;
    detecting_bit_rate_ = automatic && lss_->active_bit_rate() == *automatic;
  }
  reset_application();
  reset_communication();
  boot_due_ = now + policy_.nmt.boot_delay;
  refresh_rx_gate();
}

void Node::power_off() {
  const bool was_powered = powered_;
  powered_ = false;
  if (was_powered) {
    const CauseScope scope(*this, {TransitionCause::Power, 0, "", "power off"});
    record_nmt(to_string(status_.nmt_state), "OFF");
    app().on_power_off();
  }
  boot_pending_ = false;
  refresh_rx_gate();
  status_.nmt_state = NmtState::Initialising;
  sdo_->reset();
}

void Node::reset_application() {
  store_->load_area(0x2000, 0xFFFF);
  app().on_reset_application();
}

void Node::reset_communication() {
  status_.nmt_state = NmtState::Initialising;
  app().on_reset_communication();
  status_.node_id = status_.pending_node_id;
  store_->load_area(0x1000, 0x1FFF);
  sdo_->reset();
  emcy_->reset_communication();
  heartbeat_consumer_->reload();
  pdo_->reload();
  app().after_reset_communication();
  rebuild_dispatch();
  boot_pending_ = true;
  refresh_rx_gate();
  boot_due_ = status_.now + policy_.nmt.reset_delay;
}

void Node::send_boot_up() {
  boot_pending_ = false;
  refresh_rx_gate();
  // LSS only until configured.
  if (status_.node_id == kUnconfigured || status_.node_id == 0 || status_.node_id > 127) return;
  const NmtState from = status_.nmt_state;
  status_.nmt_state = NmtState::PreOperational;  // boot-up is sent on the transition (EMCY allowed after)
  NmtCause boot = boot_cause_;
  boot.transition = "boot-up";
  const CauseScope scope(*this, boot);
  record_nmt(to_string(from), to_string(status_.nmt_state));
  send(sim::CanFrame::data_frame(0x700u + status_.node_id, {0x00}));
  error_control_->reset_communication(status_.now);
  app().on_nmt_state_changed(from, status_.nmt_state);
}

void Node::execute_nmt(NmtCommand command, std::string_view sender) {
  if (!powered_ || status_.nmt_state == NmtState::Initialising) return;
  const CauseScope scope(*this, {TransitionCause::NmtCommand, static_cast<std::uint32_t>(command), sender,
                                 command_transition(command)});
  app().on_nmt_command(command);
  switch (command) {
    case NmtCommand::Start: set_nmt_state(NmtState::Operational); break;
    case NmtCommand::Stop: set_nmt_state(NmtState::Stopped); break;
    case NmtCommand::EnterPreOperational: set_nmt_state(NmtState::PreOperational); break;
    case NmtCommand::ResetNode:
    case NmtCommand::ResetCommunication:
      record_nmt(to_string(status_.nmt_state), "INITIALISING");
      status_.nmt_state = NmtState::Initialising;
      boot_cause_ = cause_;  // the boot-up that follows names the reset
      if (command == NmtCommand::ResetNode) reset_application();
      reset_communication();
      break;
  }
}

void Node::set_nmt_state(NmtState state) {
  if (state == status_.nmt_state) return;
  const NmtState from = status_.nmt_state;
  status_.nmt_state = state;
  record_nmt(to_string(from), to_string(state));
  if (state == NmtState::Operational) pdo_->on_enter_operational(status_.now);
  app().on_nmt_state_changed(from, state);
}

void Node::record_nmt(std::string_view from, std::string_view to) {
  if (!transitions_ || from == to) return;
  transitions_->record({0, static_cast<std::uint64_t>(status_.now.time_since_epoch().count()), "nmt", from, to,
                        cause_.transition, cause_.cause, cause_.value, cause_.detail});
}

void Node::communication_error(CommError error, std::uint32_t evidence) {
  // A state change that follows (1029h:01, or the product's own reaction) names the error.
  const TransitionCause cause = error == CommError::HeartbeatConsumer ? TransitionCause::HeartbeatTimeout
                                : error == CommError::LifeGuarding   ? TransitionCause::GuardingTimeout
                                                                     : TransitionCause::BusOff;
  const CauseScope scope(*this, {cause, evidence, error == CommError::BusOffRecovered ? "recovered" : "", "1029h:01"});
  if (app().on_communication_error(error)) return;
  const auto& p = policy_.error_control;
  if (error == CommError::BusOffRecovered) {
    // An event, not a lasting condition: nothing clears it later.
    if (p.bus_off_recovered_emcy != 0) emcy_->signal(p.bus_off_recovered_emcy, p.communication_error_register);
  } else {
    const std::uint16_t code = error == CommError::HeartbeatConsumer ? p.heartbeat_consumer_emcy : p.life_guard_emcy;
    if (code != 0) emcy_->raise(code, p.communication_error_register);
  }
  if (const auto* behaviour = od_.entry(kErrorBehaviour, 1)) {
    switch (behaviour->as<std::uint8_t>()) {
      case 0:
        if (status_.nmt_state == NmtState::Operational) set_nmt_state(NmtState::PreOperational);
        break;
      case 2: set_nmt_state(NmtState::Stopped); break;
      default: break;  // 1: no state change
    }
  }
}

void Node::raise_emcy(std::uint16_t code) { emcy_->raise(code, policy_.error_control.communication_error_register); }

void Node::clear_emcy(std::uint16_t code) { emcy_->clear(code); }

void Node::sync_received(std::uint8_t pdo_counter, std::uint8_t counter, sim::Time now) {
  pdo_->on_sync(pdo_counter, now);
  app().on_sync(counter);
}

void Node::communication_recovered(CommError error) {
  app().on_communication_recovered(error);
  const auto& p = policy_.error_control;
  const std::uint16_t code = error == CommError::HeartbeatConsumer ? p.heartbeat_consumer_emcy : p.life_guard_emcy;
  if (code == 0) return;
  // Clear only when no other communication watchdog still reports the same code.
  const bool guard_bad = error_control_->life_guarding_error() && p.life_guard_emcy == code;
  const bool hb_bad = heartbeat_consumer_->any_timed_out() && p.heartbeat_consumer_emcy == code;
  if (!guard_bad && !hb_bad) emcy_->clear(code);
}

// ---- dispatch -----------------------------------------------------------------------------------

void Node::add_route(std::uint32_t cob_id, Route r, std::uint8_t index) {
  if (cob_id <= 0x7FF) {
    routes_[cob_id] = RouteEntry{r, index};
  } else {
    extended_routes_.push_back(ExtendedRoute{cob_id, RouteEntry{r, index}});
  }
}

void Node::rebuild_dispatch() {
  routes_.fill(RouteEntry{});
  extended_routes_.clear();
  // Lowest priority first: later routes win on a clash (the own services over consumers).
  for (auto producer : heartbeat_consumer_->producers()) add_route(0x700u + producer, Route::HeartbeatConsumer);
  for (const auto& r : pdo_->tpdo_routes()) add_route(r.cob_id | (r.extended ? 0x80000000u : 0), Route::TpdoRtr, static_cast<std::uint8_t>(r.number));
  for (const auto& r : pdo_->rpdo_routes()) add_route(r.cob_id | (r.extended ? 0x80000000u : 0), Route::Rpdo, static_cast<std::uint8_t>(r.number));
  add_route(sync_->cob_id() | (sync_->extended() ? 0x80000000u : 0), Route::Sync);
  const std::uint32_t sdo_rx = sdo_->rx_cob_id();
  if (!(sdo_rx & 0x80000000u)) add_route(sdo_rx & ((sdo_rx & 0x20000000u) ? 0x9FFFFFFFu : 0x7FFu), Route::SdoRx);
  if (status_.node_id >= 1 && status_.node_id <= 127) add_route(0x700u + status_.node_id, Route::ErrorControl);
  if (lss_) add_route(kLssMasterToSlave, Route::Lss);
  add_route(0x000, Route::Nmt);
}

void Node::on_frame(const sim::CanFrame& frame, sim::Time now) {
  // Every frame on the bus comes here, most of them for other nodes (Route::None): that path and
  // the SYNC's make no call but the one they need; the other routes go through dispatch().
  const auto route_frame = [&](const RouteEntry& route) {
    if (route.route == Route::None) {
      ++stats_.ignored_frames;
      return;
    }
    if (route.route == Route::Sync) {
      sync_->on_frame(frame, now);
      return;
    }
    dispatch(route, frame, now);
  };
  if (rx_plain_) {  // the usual state: what is left of the checks below
    status_.now = now;
    if (silent() || !on_bus_rate()) return;
    ++stats_.rx_frames;
    route_frame(frame.extended ? extended_route(frame.id) : routes_[frame.id & 0x7FF]);
    return;
  }
  if (!powered_) return;
  status_.now = now;
  if (silent() || bus_off_ || !on_bus_rate()) return;
  if (detecting_bit_rate_) {
    detect_bit_rate(now);
    return;
  }
  ++stats_.rx_frames;
  const RouteEntry route = frame.extended ? extended_route(frame.id) : routes_[frame.id & 0x7FF];
  if (route.route != Route::Lss) {
    if (status_.node_id < 1 || status_.node_id > 127) return;  // unconfigured: LSS only
    if (boot_pending_) return;                                  // still initialising
  }
  route_frame(route);
}

void Node::detect_bit_rate(sim::Time now) {
  // The frame only serves to measure the bit rate (it is not processed); boot-up follows.
  detecting_bit_rate_ = false;
  refresh_rx_gate();
  detected_kbit_ = bus_ ? bus_->bit_rate_kbit() : 0;
  boot_due_ = now + policy_.nmt.boot_delay;
}

Node::RouteEntry Node::extended_route(std::uint32_t id) const {
  RouteEntry route;
  const std::uint32_t key = id | 0x80000000u;
  for (const auto& r : extended_routes_)
    if (r.id == key) route = r.entry;
  return route;
}

void Node::dispatch(RouteEntry route, const sim::CanFrame& frame, sim::Time now) {
  switch (route.route) {
    case Route::Nmt: nmt_->on_frame(frame); break;
    case Route::Sync: sync_->on_frame(frame, now); break;
    case Route::Rpdo: pdo_->on_rpdo(route.index, frame, now); break;
    case Route::TpdoRtr: pdo_->on_tpdo_rtr(route.index, frame, now); break;
    case Route::SdoRx:
      if (sdo_allowed(status_.nmt_state)) sdo_->on_request(frame, now);
      break;
    case Route::ErrorControl:
      if (error_control_allowed(status_.nmt_state)) error_control_->on_frame(frame, now);
      break;
    case Route::HeartbeatConsumer: heartbeat_consumer_->on_frame(frame, now); break;
    case Route::Lss: lss_->on_frame(frame, now); break;
    case Route::None: ++stats_.ignored_frames; break;
  }
}

void Node::on_error_state(sim::ErrorState state, sim::Time now) {
  const sim::ErrorState previous = controller_state_;
  controller_state_ = state;
  if (!powered_) return;
  if (now > status_.now) status_.now = now;
  if (state == sim::ErrorState::BusOff) {
    bus_off_ = true;
    refresh_rx_gate();
    return;
  }
  const auto& p = policy_.error_control;
  if (state == sim::ErrorState::Passive && previous == sim::ErrorState::Active) {
    if (!app().on_error_passive(true) && p.error_passive_emcy != 0) emcy_->raise(p.error_passive_emcy, p.communication_error_register);
  } else if (state == sim::ErrorState::Active && previous != sim::ErrorState::Active) {
    if (!app().on_error_passive(false) && p.error_passive_emcy != 0) emcy_->clear(p.error_passive_emcy);
  }
  if (previous == sim::ErrorState::BusOff) {
    bus_off_ = false;
    refresh_rx_gate();
    communication_error(CommError::BusOffRecovered);
  }
}

void Node::step(sim::Time now, sim::Duration dt) {
  if (!powered_) return;
  status_.now = now;
  // Services with nothing to do are skipped by an inline check (most ticks: all but the
  // heartbeat timer, the application and the PDOs).
  if (lss_ && !lss_->idle()) lss_->process(now);  // runs while silent: it ends an "activate bit timing" pause
  if (silent() || detecting_bit_rate_) return;
  if (boot_pending_ && now >= boot_due_) send_boot_up();
  if (boot_pending_ || status_.nmt_state == NmtState::Initialising) return;
  if (!sdo_->idle()) sdo_->process(now);
  if (!error_control_->idle(now)) error_control_->process(now);
  if (!heartbeat_consumer_->idle()) heartbeat_consumer_->process(now);
  app().process(now, dt);
  pdo_->process(now);
  if (!emcy_->idle()) emcy_->process(now);
}

}  // namespace canopen
