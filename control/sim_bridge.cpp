#include "control/sim_bridge.h"

#include <algorithm>
#include <thread>

#include "devices/canopen/emergency.h"
#include "engine/loading/scenario.h"
#include "engine/running/world.h"
#include "sim/scheduler.h"

namespace control {

namespace {
constexpr int kMaxPdos = 8;  // per direction and node: what the decoder and the dashboard show
constexpr sim::Duration kSdoTimeout = sim::milliseconds(1000);
constexpr auto kSdoWallTimeout = std::chrono::seconds(3);
constexpr auto kStopPoll = std::chrono::milliseconds(20);  // how soon a paced wait sees a stop
constexpr double kMaxPaceWaitUs = 3600e6;                  // a wall hour: far beyond any tick

bool same_profile(const devices::ProfileStatus& a, const devices::ProfileStatus& b) {
  return a.profile == b.profile && a.state == b.state && a.control_word == b.control_word &&
         a.status_word == b.status_word && a.transitions == b.transitions && a.fault_count == b.fault_count &&
         a.faults == b.faults && a.operating_status == b.operating_status && a.alarms == b.alarms &&
         a.warnings == b.warnings;
}

bool same_map(const PdoMap& a, const PdoMap& b) {
  return a.cob_id == b.cob_id && a.valid == b.valid && a.transmit == b.transmit && a.number == b.number &&
         a.count == b.count && a.entries == b.entries;
}
}  // namespace

bool NodeStatus::same_as(const NodeStatus& o) const {
  if (!(powered == o.powered && nmt == o.nmt && node_id == o.node_id && error_register == o.error_register &&
        emcy_count == o.emcy_count && same_profile(profile, o.profile) && channel_count == o.channel_count))
    return false;
  for (std::size_t c = 0; c < channel_count; ++c)
    if (!(channels[c] == o.channels[c])) return false;
  return true;
}

/// Sees every frame on one bus (scheduler thread): EMCY history always, the capture ring while
/// a stream listens (a plain copy; the ring is published once per tick).
class SimBridge::BusTap final : public sim::FrameTap {
 public:
  BusTap(SimBridge* bridge, std::size_t bus) : bridge_(bridge), bus_(bus) {}
  void on_bus_frame(std::string_view, const sim::CanFrame& f, sim::Time now) override {
    if (bridge_->capturing_) {
      if (auto* slot = bridge_->frames_.claim()) {
        slot->t_us = now.time_since_epoch().count();
        slot->bus = static_cast<std::uint8_t>(bus_);
        slot->frame = f;
        bridge_->frames_.commit();
      } else {
        ++bridge_->dropped_;
      }
    }
    if (!f.extended && !f.rtr && (f.id & 0x780) == 0x080 && (f.id & 0x7F) != 0) bridge_->record_emcy(bus_, f, now);
  }

 private:
  SimBridge* bridge_;
  std::size_t bus_;
};

/// The control plane's own endpoint on a bus: it sends NMT, raw frames and SDO requests, and
/// feeds SDO responses to its client.
class SimBridge::BusMaster final : public sim::FrameReceiver {
 public:
  BusMaster(sim::Bus& bus, sim::Scheduler& scheduler)
      : bus_(bus), scheduler_(scheduler), sdo([this](const sim::CanFrame& f) { send(f); }) {
    endpoint_ = bus_.attach(this);
  }
  void on_frame(const sim::CanFrame& f, sim::Time now) override {
    if (sdo.busy()) sdo.on_frame(f, now);
  }
  void send(const sim::CanFrame& f) { bus_.send(endpoint_, f, scheduler_.now()); }

 private:
  sim::Bus& bus_;
  sim::Scheduler& scheduler_;
  int endpoint_ = -1;

 public:
  scenario::SdoClient sdo;
};

struct SimBridge::SdoJob {
  std::shared_ptr<std::promise<SdoOutcome>> promise;
  std::chrono::steady_clock::time_point wall_deadline;
};

SimBridge::SimBridge(ClockOptions clock) : options_(clock) {}
SimBridge::~SimBridge() = default;

void SimBridge::attach(const scenario::RunContext& context) {
  const bool again = ctx_ != nullptr;  // a restart
  if (again) forget_run();
  ctx_ = std::make_unique<scenario::RunContext>(context);
  auto& world = ctx_->world;
  realtime_ = ctx_->scheduler.mode() == sim::ClockMode::RealTime;
  if (!again) {
    paused_ = !realtime_ && options_.start_paused;
    speed_ = options_.speed;
  }
  now_us_ = ctx_->scheduler.now().time_since_epoch().count();
  tick_us_ = ctx_->scheduler.tick().count();

  for (std::size_t b = 0; b < world.buses().size(); ++b) {
    auto& bus = *world.buses()[b];
    taps_.push_back(std::make_unique<BusTap>(this, b));
    bus.add_tap(taps_.back().get());
  }
  masters_.resize(world.buses().size());
  sync_.assign(world.buses().size(), {});
  sync_on_ = false;
  sdo_jobs_.resize(world.buses().size());
  node_by_id_.assign(world.buses().size(), {});
  for (auto& t : node_by_id_) t.fill(-1);

  const auto n = world.nodes().size();
  work_.resize(n);
  transition_seen_.assign(n, 0);
  pdo_work_.assign(n, std::vector<PdoMap>(2 * kMaxPdos));
  std::vector<SignalInfo> signals;
  for (const auto& node : world.nodes())
    for (const auto& p : node.ports) signals.push_back({node.spec->name + "." + p.name, p.unit, p.value, p.display});
  if (auto* plant = world.plant())
    for (const auto& p : plant->ports()) signals.push_back({p.name, p.unit, p.value, p.display});
  if (!again) {
    signals_ = std::move(signals);
    signal_rows_ = std::make_unique<SpscRing<SignalRow>>(512, SignalRow{0, std::vector<double>(signals_.size())});
  } else {
    // The same scenario has the same signals: only where they live changed (the names stay, the
    // stream thread reads them).
    for (std::size_t k = 0; k < signals_.size() && k < signals.size(); ++k) signals_[k].value = signals[k].value;
  }

  publish_nodes(now_us_.load(std::memory_order_relaxed), true);
  refresh_pdo_maps();
  if (again) {
    restarts_.fetch_add(1);
    for (auto& w : restart_waiters_) w->set_value(true);
    restart_waiters_.clear();
  }
  attached_ = true;
}

void SimBridge::forget_run() {
  // The old run's world is gone: its buses (taps, endpoints), SDO transfers, faults and SYNC.
  for (auto& job : sdo_jobs_) {
    if (job) job->promise->set_value({SdoOutcome::Kind::Failed, {}, 0, "the scenario restarted"});
    job.reset();
  }
  sdo_active_ = 0;
  taps_.clear();
  masters_.clear();
  live_faults_.clear();
  restart_pending_ = false;
  end_seen_ = false;
  end_reached_ = false;
  budget_ = 0;
  anchor_valid_ = false;
  next_sample_us_ = 0;
  work_.assign(work_.size(), NodeStatus{});
  dirty_ = true;
  pdo_dirty_ = true;
}

std::future<bool> SimBridge::request_restart() {
  auto promise = std::make_shared<std::promise<bool>>();
  auto future = promise->get_future();
  if (!post([this, promise](const scenario::RunContext&) {
        restart_pending_ = true;
        anchor_valid_ = false;  // a paced wait returns at once
        restart_waiters_.push_back(promise);
      }))
    promise->set_value(false);
  return future;
}

void SimBridge::detach() {
  {
    std::lock_guard lk(queue_mu_);
    finished_ = true;
    queue_.clear();  // their promises break: waiting server threads answer at once
  }
  for (auto& job : sdo_jobs_) {
    if (job) job->promise->set_value({SdoOutcome::Kind::Failed, {}, 0, "the run has ended"});
    job.reset();
  }
  sdo_active_ = 0;
  for (auto& w : restart_waiters_) w->set_value(false);
  restart_waiters_.clear();
  publish_capture();  // what the last ticks captured still reaches the stream
  wake_.notify_all();
}

SimBridge::Posted SimBridge::try_post(Command command) {
  {
    std::lock_guard lk(queue_mu_);
    if (finished_) return Posted::Ended;
    if (queue_.size() >= kMaxQueuedCommands) return Posted::Full;
    queue_.push_back(std::move(command));
    wanted_.fetch_or(kWantCommands, std::memory_order_release);
  }
  wake_.notify_all();
  return Posted::Queued;
}

bool SimBridge::drain_commands() {
  {
    std::unique_lock lk(queue_mu_, std::try_to_lock);
    if (!lk) {  // a server thread is queueing: next boundary
      wanted_.fetch_or(kWantCommands, std::memory_order_relaxed);
      return false;
    }
    running_.swap(queue_);
  }
  for (auto& c : running_) c(*ctx_);
  running_.clear();
  return true;
}

bool SimBridge::before_tick(bool end_reached) {
  auto& sched = ctx_->scheduler;
  if (end_reached && !end_seen_) {
    end_seen_ = true;
    end_reached_ = true;
    if (realtime_) return false;  // real time ends at its duration: nobody can pause it
    paused_ = true;               // virtual time waits for the dashboard instead of ending
    budget_ = 0;
  }
  service();
  if (realtime_) return tick_goes_ahead();
  while (!sched.stop_requested() && !restart_pending_) {
    if (!paused_.load()) {
      pace();
      break;
    }
    if (const auto b = budget_.load(); b > 0) {
      budget_ = b - 1;
      pace();
      break;
    }
    // On a bit-timed bus a request and its answer take wire time: a paused clock still runs the
    // ticks an SDO transfer needs (bounded by the client's virtual-time timeout).
    if (sdo_in_flight()) {
      pace();
      break;
    }
    anchor_valid_ = false;
    wait_for_work(std::chrono::steady_clock::now() + kStopPoll);
    service();
  }
  return tick_goes_ahead();
}

bool SimBridge::tick_goes_ahead() {
  if (ctx_->scheduler.stop_requested() || restart_pending_) return false;
  // The control plane's SYNCs due at this tick go out with it (none while the clock stands).
  if (sync_on_) produce_sync();
  return true;
}

void SimBridge::service() {
  const std::int64_t now = ctx_->scheduler.now().time_since_epoch().count();
  bool snapshot = false;
  if (wanted_.load(std::memory_order_relaxed) != 0) {
    const unsigned wanted = wanted_.exchange(0, std::memory_order_acquire);
    if (wanted & kWantCommands) {
      if (drain_commands()) {
        ctx_->scheduler.deliver_all();  // what the commands sent arrives now, paused or not
        snapshot = true;                // and a reader sees what they changed
      }
    }
    snapshot |= (wanted & kWantSnapshot) != 0;
  }
  // A clock that stands (paused, nothing left to step) publishes what it stands at, waiting for
  // the lock if a reader holds it (nothing runs that could be late), so a reader that sees the
  // clock stand sees the nodes as they are.
  const bool standing = !realtime_ && paused_.load(std::memory_order_relaxed) &&
                        budget_.load(std::memory_order_relaxed) == 0 && sdo_active_ == 0;
  if (sdo_active_ > 0) finish_sdo_jobs();
  capturing_ = listeners_.load(std::memory_order_relaxed) > 0;
  if (snapshot || standing) {
    publish_nodes(now, standing);
    // PDO mappings (for decoding the stream) change by SDO: re-read them with the snapshot.
    if (capturing_ && snapshot) refresh_pdo_maps();
  }
  if (capturing_) {
    if (now >= next_sample_us_) sample_signals(now);
    publish_capture();
  } else if (frames_.unpublished()) {
    publish_capture();
  }
  // Last: a reader that sees the new time sees the snapshot taken at it.
  now_us_.store(now, std::memory_order_release);
}

void SimBridge::publish_capture() {
  frames_.publish();
  if (signal_rows_) signal_rows_->publish();
  frames_dropped_.store(dropped_, std::memory_order_relaxed);
}

void SimBridge::pace() {
  const double speed = speed_.load();
  if (speed <= 0) {
    anchor_valid_ = false;
    return;
  }
  const auto now_sim = ctx_->scheduler.now().time_since_epoch().count();
  if (!anchor_valid_) {
    anchor_wall_ = std::chrono::steady_clock::now();
    anchor_sim_us_ = now_sim;
    anchor_valid_ = true;
    return;
  }
  // In double, clamped before the conversion: no speed or span can overflow the wall offset.
  const double wall_us = std::min(static_cast<double>(now_sim - anchor_sim_us_) / speed, kMaxPaceWaitUs);
  const auto target = anchor_wall_ + std::chrono::microseconds(static_cast<std::int64_t>(wall_us));
  while (!ctx_->scheduler.stop_requested() && std::chrono::steady_clock::now() < target) {
    // In slices: a stop request (a signal handler sets a flag, it cannot notify) is seen at once.
    wait_for_work(std::min(target, std::chrono::steady_clock::now() + kStopPoll));
    service();
    if (!anchor_valid_ || speed_.load() != speed) return;  // re-anchored by a clock command
  }
}

void SimBridge::wait_for_work(std::chrono::steady_clock::time_point until) {
  std::unique_lock lk(queue_mu_);
  wake_.wait_until(lk, until, [this] { return (wanted_.load(std::memory_order_relaxed) & kWantCommands) || finished_.load(); });
}

ClockState SimBridge::clock() const {
  ClockState c;
  c.realtime = realtime_;
  c.t_us = now_us_.load(std::memory_order_acquire);
  c.tick_us = tick_us_.load(std::memory_order_relaxed);
  c.run_ticks_left = budget_.load();
  c.paused = paused_.load() && c.run_ticks_left == 0;
  c.speed = speed_.load();
  c.end_reached = end_reached_.load();
  return c;
}

bool SimBridge::pause() {
  return post([this](const scenario::RunContext&) {
    paused_ = true;
    budget_ = 0;
    anchor_valid_ = false;
  });
}

bool SimBridge::resume(std::optional<double> speed) {
  return post([this, speed](const scenario::RunContext&) {
    if (speed) speed_ = *speed;
    paused_ = false;
    budget_ = 0;
    anchor_valid_ = false;
  });
}

bool SimBridge::run_ticks(std::uint64_t ticks) {
  return post([this, ticks](const scenario::RunContext&) {
    paused_ = true;
    budget_ = ticks;
    anchor_valid_ = false;
  });
}

std::future<SdoOutcome> SimBridge::sdo(std::size_t node, bool upload, std::uint16_t index, std::uint8_t sub,
                                       std::vector<std::uint8_t> data) {
  auto promise = std::make_shared<std::promise<SdoOutcome>>();
  auto future = promise->get_future();
  const bool queued = post([this, promise, node, upload, index, sub, data = std::move(data)](const scenario::RunContext& c) {
    auto& n = c.world.nodes()[node];
    const auto bus = static_cast<std::size_t>(n.bus);
    if (sdo_jobs_[bus]) {
      promise->set_value({SdoOutcome::Kind::Busy, {}, 0, "another SDO transfer is running on this bus"});
      return;
    }
    auto& client = master(bus).sdo;
    client.reset();
    const auto id = n.device->node().node_id();
    if (upload) client.start_upload(id, index, sub, c.scheduler.now(), kSdoTimeout);
    else client.start_download(id, index, sub, data, c.scheduler.now(), kSdoTimeout);
    sdo_jobs_[bus] = std::make_unique<SdoJob>(SdoJob{promise, std::chrono::steady_clock::now() + kSdoWallTimeout});
    ++sdo_active_;
  });
  if (!queued) promise->set_value({SdoOutcome::Kind::Failed, {}, 0, "the run has ended"});
  return future;
}

bool SimBridge::sdo_in_flight() const { return sdo_active_ > 0; }

SimBridge::BusMaster& SimBridge::master(std::size_t bus) {
  auto& m = masters_[bus];
  if (!m) m = std::make_unique<BusMaster>(*ctx_->world.buses()[bus], ctx_->scheduler);
  return *m;
}

void SimBridge::finish_sdo_jobs() {
  for (std::size_t b = 0; b < sdo_jobs_.size(); ++b) {
    auto& job = sdo_jobs_[b];
    if (!job) continue;
    auto& client = master(b).sdo;
    client.poll(ctx_->scheduler.now());
    SdoOutcome out;
    switch (client.state()) {
      case scenario::SdoClient::State::Busy:
        if (std::chrono::steady_clock::now() < job->wall_deadline) continue;
        client.reset();
        out.kind = SdoOutcome::Kind::Failed;
        out.error = paused_.load() ? "no answer while the clock is paused (the node answers when time runs)"
                                   : "no answer within 3 s";
        break;
      case scenario::SdoClient::State::Done:
        out.kind = SdoOutcome::Kind::Done;
        out.data = client.data();
        break;
      case scenario::SdoClient::State::Aborted:
        out.kind = SdoOutcome::Kind::Aborted;
        out.abort_code = client.abort_code();
        break;
      case scenario::SdoClient::State::Failed:
        out.kind = SdoOutcome::Kind::Failed;
        out.abort_code = client.abort_code();
        out.error = client.error();
        break;
      case scenario::SdoClient::State::Idle:
        out.kind = SdoOutcome::Kind::Failed;
        out.error = "the transfer did not start";
        break;
    }
    client.reset();
    job->promise->set_value(std::move(out));
    job.reset();
    --sdo_active_;
  }
}

void SimBridge::record_emcy(std::size_t bus, const sim::CanFrame& f, sim::Time now) {
  const int index = node_by_id_[bus][f.id & 0x7F];
  if (index < 0) return;
  auto& st = work_[static_cast<std::size_t>(index)];
  auto& r = st.emcy[st.emcy_count % NodeStatus::kEmcyHistory];
  r.t_us = now.time_since_epoch().count();
  r.code = static_cast<std::uint16_t>(f.data[0] | f.data[1] << 8);
  r.error_register = f.dlc >= 3 ? f.data[2] : 0;
  for (std::size_t i = 0; i < 5; ++i) r.data[i] = f.dlc > 3 + i ? f.data[3 + i] : 0;
  ++st.emcy_count;
}

void SimBridge::capture_transitions() {
  auto& nodes = ctx_->world.nodes();
  bool any = false;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto& log = nodes[i].device->transition_log();
    if (log.last_seq() == transition_seen_[i]) continue;
    if (capturing_) {
      log.for_each_after(transition_seen_[i], [&](const devices::Transition& t) {
        if (auto* slot = transitions_.claim()) {
          slot->node = static_cast<std::uint32_t>(i);
          slot->transition = t;
          transitions_.commit();
        }
      });
      any = true;  // publish also learns what the hub took (a full ring frees up)
    }
    transition_seen_[i] = log.last_seq();
  }
  if (any) transitions_.publish();
}

void SimBridge::publish_nodes(std::int64_t now, bool wait) {
  capture_transitions();
  auto& nodes = ctx_->world.nodes();
  bool ids_changed = false;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    auto& dev = *nodes[i].device;
    auto& node = dev.node();
    auto& st = work_[i];
    st.powered = node.powered();
    st.nmt = static_cast<std::uint8_t>(node.nmt_state());
    ids_changed |= st.node_id != node.node_id();
    st.node_id = node.node_id();
    st.error_register = node.emergency().error_register();
    const auto before = st.profile.transitions;
    st.profile = dev.profile_status();
    if (st.profile.transitions != before) st.transition_t_us = now;
    if (const int channels = dev.profile_channel_count(); channels > 0) {
      st.channel_count = static_cast<std::uint8_t>(std::min<int>(channels, NodeStatus::kMaxChannels));
      for (std::size_t c = 0; c < st.channel_count; ++c) {
        const auto p = dev.channel_profile_status(static_cast<int>(c) + 1);
        auto& ch = st.channels[c];
        if (p.transitions != ch.transitions) ch.transition_t_us = now;
        ch.state = p.state;
        ch.control_word = p.control_word;
        ch.status_word = p.status_word;
        ch.transitions = p.transitions;
        ch.transition_from = p.transition_from;
        ch.transition_to = p.transition_to;
        ch.transition_control_word = p.transition_control_word;
      }
    }
  }
  if (ids_changed) {
    for (auto& t : node_by_id_) t.fill(-1);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto id = work_[i].node_id;
      if (id >= 1 && id <= 127) node_by_id_[static_cast<std::size_t>(nodes[i].bus)][id] = static_cast<int>(i);
    }
  }
  if (!dirty_) {
    if (last_.size() != work_.size()) dirty_ = true;
    for (std::size_t i = 0; !dirty_ && i < work_.size(); ++i) dirty_ = !work_[i].same_as(last_[i]);
  }
  if (!dirty_) return;
  std::unique_lock lk(pub_mu_, std::defer_lock);
  if (wait) lk.lock();
  else if (!lk.try_lock()) return;  // a reader holds it: publish at the next snapshot
  published_ = work_;
  last_ = work_;
  node_version_.fetch_add(1);
  dirty_ = false;
}

std::uint64_t SimBridge::nodes(std::vector<NodeStatus>& out) const {
  std::lock_guard lk(pub_mu_);
  out = published_;
  return node_version_.load();
}

void SimBridge::refresh_pdo_maps() {
  auto& nodes = ctx_->world.nodes();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto& od = nodes[i].device->node().od();
    for (int k = 0; k < 2 * kMaxPdos; ++k) {
      const bool transmit = k >= kMaxPdos;
      const int n = k % kMaxPdos;
      const auto comm = static_cast<std::uint16_t>((transmit ? 0x1800 : 0x1400) + n);
      const auto mapping = static_cast<std::uint16_t>((transmit ? 0x1A00 : 0x1600) + n);
      PdoMap m;
      m.transmit = transmit;
      m.number = static_cast<std::uint8_t>(n + 1);
      if (const auto* c = od.entry(comm, 1)) {
        const auto v = c->as<std::uint32_t>();
        m.valid = !(v & 0x80000000u) && !(v & 0x20000000u);
        m.cob_id = v & 0x7FF;
        if (const auto* count = od.entry(mapping, 0)) {
          m.count = static_cast<std::uint8_t>(std::min<unsigned>(count->as<std::uint8_t>(), PdoMap::kMaxEntries));
          for (std::uint8_t s = 0; s < m.count; ++s) {
            const auto* e = od.entry(mapping, static_cast<std::uint8_t>(s + 1));
            m.entries[s] = e ? e->as<std::uint32_t>() : 0;
          }
        }
      }
      auto& slot = pdo_work_[i][static_cast<std::size_t>(k)];
      if (!same_map(slot, m)) {
        slot = m;
        pdo_dirty_ = true;
      }
    }
  }
  if (!pdo_dirty_) return;
  std::unique_lock lk(pub_mu_, std::try_to_lock);
  if (!lk) return;
  pdo_published_ = pdo_work_;
  ++pdo_version_;
  pdo_dirty_ = false;
}

std::uint64_t SimBridge::pdo_maps(std::vector<std::vector<PdoMap>>& out) const {
  std::lock_guard lk(pub_mu_);
  out = pdo_published_;
  return pdo_version_.load();
}

void SimBridge::sample_signals(std::int64_t now) {
  next_sample_us_ = now + signal_period_us_;
  auto* row = signal_rows_->claim();
  if (!row) return;  // the stream is behind: a gap in the plot, counted nowhere else
  row->t_us = now;
  for (std::size_t i = 0; i < signals_.size(); ++i) row->values[i] = *signals_[i].value;
  signal_rows_->commit();
}

bool SimBridge::send_frame(std::size_t bus, const sim::CanFrame& frame) {
  const auto& stats = ctx_->world.buses()[bus]->stats();
  const auto refused = stats.tx_queue_overflow;
  master(bus).send(frame);
  return stats.tx_queue_overflow == refused;
}

void SimBridge::set_sync(std::size_t bus, sim::Duration period, std::uint8_t counter_overflow) {
  master(bus);  // its endpoint exists before the first SYNC (nothing allocates in produce_sync)
  sync_[bus].start(period, counter_overflow, ctx_->scheduler.now());
  sync_on_ = std::any_of(sync_.begin(), sync_.end(), [](const scenario::SyncProducer& p) { return p.period.count() > 0; });
}

void SimBridge::produce_sync() {
  const auto now = ctx_->scheduler.now();
  for (std::size_t b = 0; b < sync_.size(); ++b)
    if (const auto f = sync_[b].due(now)) masters_[b]->send(*f);
}

void SimBridge::add_listener() {
  if (listeners_.fetch_add(1) == 0)
    post([this](const scenario::RunContext&) { refresh_pdo_maps(); });
}
void SimBridge::remove_listener() { listeners_.fetch_sub(1); }

}  // namespace control
