#include "control/event_hub.h"

#include <algorithm>

#include "control/json_views.h"
#include "control/machine_views.h"
#include "control/pdo_view.h"
#include "engine/running/world.h"
#include "sim/scheduler.h"
#include "control/server_thread_priority.h"
#include "engine/running/master_findings.h"
#include "engine/running/master_monitor.h"

namespace control {

namespace {
constexpr auto kBatchPeriod = std::chrono::milliseconds(50);
constexpr auto kSnapshotPeriod = std::chrono::milliseconds(20);  // 50 Hz
constexpr std::size_t kMaxBacklog = 4 << 20;        // bytes per client
constexpr std::size_t kMaxSharedBacklog = 256 << 10;  // bytes per shared (read-only) client
// The selected node's dictionary and the live faults: 5 times a wall second is what a table
// on a page shows; reading them costs the scheduler one command.
constexpr auto kLiveTablePeriod = std::chrono::milliseconds(200);
constexpr auto kLiveTableWait = std::chrono::milliseconds(150);
// Frames decoded per batch: 40 000 a second, more than two 1 Mbit/s buses carry; beyond (full
// virtual speed) the stream is a sample.
constexpr std::size_t kMaxFramesPerBatch = 2048;
// Findings per `findings` event: a burst beyond goes out over the next reads, 200 ms apart.
constexpr std::size_t kFindingsPerEvent = 100;

void append_event(std::string& out, const char* name, const std::string& data) {
  out += "event: ";
  out += name;
  out += "\ndata: ";
  out += data;
  out += "\n\n";
}
}  // namespace

bool EventHub::Client::next(std::string& out, std::chrono::milliseconds timeout) {
  std::unique_lock lk(mu_);
  cv_.wait_for(lk, timeout, [this] { return closed_ || !outbox_.empty(); });
  out.clear();
  out.swap(outbox_);
  return !closed_;
}

EventHub::EventHub(SimBridge& bridge, const DictionaryCatalog& catalog, StreamTopology topology, std::size_t max_clients,
                   ExerciseHost* exercises)
    : bridge_(bridge), catalog_(catalog), topo_(std::move(topology)), max_clients_(max_clients), exercises_(exercises) {
  for (std::size_t b = 0; b < topo_.bus_names.size(); ++b)
    decoders_.push_back(std::make_unique<BusDecoderContext>(catalog_, static_cast<int>(b)));
  captured_.reserve(bridge_.frames().capacity());
}

EventHub::~EventHub() { stop(); }

void EventHub::start() {
  if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
}

void EventHub::stop() {
  {
    std::lock_guard lk(mu_);
    if (stopping_ && !thread_.joinable()) return;
    stopping_ = true;
    for (auto& c : clients_) {
      std::lock_guard clk(c->mu_);
      c->closed_ = true;
      c->cv_.notify_all();
    }
  }
  stop_cv_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::shared_ptr<EventHub::Client> EventHub::open(std::vector<std::size_t> signals, double rate_hz, int node) {
  std::lock_guard lk(mu_);
  if (stopping_) return nullptr;
  const auto shared = static_cast<std::size_t>(std::count_if(clients_.begin(), clients_.end(), [](const auto& c) { return c->shared_; }));
  auto c = std::make_shared<Client>();
  c->id_ = ++next_id_;
  if (clients_.size() - shared >= max_clients_) {
    if (shared >= kMaxSharedClients) return nullptr;
    c->shared_ = true;
  } else {
    c->signals_ = std::move(signals);
    c->node_ = node;
  }
  c->period_us_ = static_cast<std::int64_t>(1e6 / rate_hz);
  clients_.push_back(c);
  bridge_.add_listener();
  return c;
}

void EventHub::close(const std::shared_ptr<Client>& client) {
  std::lock_guard lk(mu_);
  for (auto it = clients_.begin(); it != clients_.end(); ++it) {
    if (*it != client) continue;
    clients_.erase(it);
    bridge_.remove_listener();
    return;
  }
}

bool EventHub::select_node(std::uint64_t id, int node) {
  std::lock_guard lk(mu_);
  for (auto& c : clients_) {
    if (c->id_ != id) continue;
    if (c->shared_) return false;
    std::lock_guard clk(c->mu_);
    c->node_ = node;
    c->od_sent_ = false;  // the new node's whole dictionary first
    return true;
  }
  return false;
}

void EventHub::live_tables(const std::vector<std::shared_ptr<Client>>& clients, std::vector<std::string>& out) {
  std::vector<int> nodes;
  for (const auto& c : clients) {
    std::lock_guard lk(c->mu_);
    if (c->node_ >= 0 && std::find(nodes.begin(), nodes.end(), c->node_) == nodes.end()) nodes.push_back(c->node_);
  }
  // Read on the scheduler's thread, between ticks: values are copied as the dictionary stores them
  // (a scalar inline, no allocation; one vector per node, sized once), the JSON is made here after.
  struct Tables {
    std::int64_t t_us = 0;
    std::vector<std::vector<canopen::StoredValue>> values;    ///< per node in `nodes`, per catalog entry
    std::vector<std::vector<canopen::ValueScaling>> scalings;  ///< the same, the product's documented unit
    struct Fault {
      int id;
      std::string summary;
      std::int64_t since_us, until_us;
    };
    std::vector<Fault> faults;  ///< at most the bridge's bound of live faults
    std::string findings;       ///< the verdict's new findings as a page (GET /api/findings), "" for none
    std::size_t findings_next = 0;
  };
  const auto& catalog = catalog_;
  auto& bridge = bridge_;
  const std::size_t findings_from = findings_next_;
  const std::uint64_t restarts = restarts_seen_;
  auto tables = bridge_.call<Tables>(
      [nodes, &catalog, &bridge, findings_from, restarts](const scenario::RunContext& c) {
        Tables t;
        t.t_us = c.scheduler.now().time_since_epoch().count();
        for (const int n : nodes) {
          auto& device = *c.world.nodes()[static_cast<std::size_t>(n)].device;
          const auto& od = device.node().od();
          const auto& entries = catalog.entries(static_cast<std::size_t>(n));
          auto& v = t.values.emplace_back();
          auto& sc = t.scalings.emplace_back();
          v.reserve(entries.size());
          sc.reserve(entries.size());
          for (const auto& e : entries) {
            const auto* entry = od.entry(e.index, e.sub);
            v.push_back(entry ? entry->value : canopen::StoredValue{});
            sc.push_back(device.value_scaling(e.index, e.sub));
          }
        }
        for (const auto& f : bridge.live_faults(t.t_us)) t.faults.push_back({f.id, f.summary, f.since_us, f.until_us});
        // A run restarted since the hub last looked starts its findings at 0: the next batch
        // resets the cursor, this read leaves them.
        t.findings_next = findings_from;
        if (const auto* m = c.master_monitor; m && bridge.restarts() == restarts && m->findings().size() > findings_from) {
          t.findings = scenario::findings_json(m->findings(), m->rules(), m->bus_names(), findings_from, kFindingsPerEvent);
          t.findings_next = std::min(m->findings().size(), findings_from + kFindingsPerEvent);
        }
        return t;
      },
      kLiveTableWait);
  if (!tables) return;  // the scheduler is busy or the run ended: next time
  nlohmann::json fault_list = nlohmann::json::array();
  for (const auto& f : tables->faults) {
    nlohmann::json j = {{"id", f.id}, {"summary", f.summary}, {"since_t_us", f.since_us}};
    if (f.until_us >= 0) j["until_t_us"] = f.until_us;
    fault_list.push_back(std::move(j));
  }
  const std::string faults = fault_list.dump();
  // One line of JSON per SSE data field (the page's newlines are only between its items).
  std::replace(tables->findings.begin(), tables->findings.end(), '\n', ' ');
  findings_next_ = tables->findings_next;
  for (std::size_t i = 0; i < clients.size(); ++i) {
    auto& c = *clients[i];
    std::lock_guard lk(c.mu_);
    if (c.faults_sent_ != faults) {
      c.faults_sent_ = faults;
      append_event(out[i], "faults", faults);
    }
    if (!tables->findings.empty()) append_event(out[i], "findings", tables->findings);
    if (c.node_ < 0) continue;
    const auto k = static_cast<std::size_t>(std::find(nodes.begin(), nodes.end(), c.node_) - nodes.begin());
    if (k >= tables->values.size()) continue;  // selected since the read
    const auto& values = tables->values[k];
    const auto& entries = catalog_.entries(static_cast<std::size_t>(c.node_));
    const bool full = !c.od_sent_;
    if (full) c.od_last_.assign(values.size(), {});
    nlohmann::json changed = nlohmann::json::object();
    nlohmann::json display = nlohmann::json::object();
    for (std::size_t e = 0; e < values.size() && e < entries.size(); ++e) {
      if (!full && values[e] == c.od_last_[e]) continue;
      c.od_last_[e] = values[e];
      const auto key = object_key(entries[e].index, entries[e].sub);
      const auto bytes = values[e].bytes();
      changed[key] = value_json(entries[e].type, bytes);
      if (auto text = display_text(entries[e].type, bytes, tables->scalings[k][e]); !text.empty()) display[key] = std::move(text);
    }
    c.od_sent_ = true;
    if (!full && changed.empty()) continue;
    append_event(out[i], "od",
                 nlohmann::json{{"node", topo_.node_names[static_cast<std::size_t>(c.node_)]},
                                {"t_us", tables->t_us},
                                {"full", full},
                                {"values", std::move(changed)},
                                {"display", std::move(display)}}
                     .dump());
  }
}

bool EventHub::refresh_exercise() {
  if (!exercises_) return false;
  const auto version = exercises_->version();  // before the read: a change during it is sent next time
  if (version == exercise_version_) return false;
  auto state = exercises_->state_json(kLiveTableWait);
  if (state.empty()) return false;  // the scheduler is busy: next batch
  exercise_version_ = version;
  if (state == exercise_event_) return false;
  exercise_event_ = std::move(state);
  return true;
}

std::size_t EventHub::clients() const {
  std::lock_guard lk(mu_);
  return clients_.size();
}

void EventHub::run() {
  lower_this_thread_priority();
  auto next_batch = std::chrono::steady_clock::now();
  std::unique_lock lk(mu_);
  while (!stopping_) {
    lk.unlock();
    if (bridge_.attached()) {
      // The scheduler takes a node snapshot only when asked: at most kSnapshotPeriod apart.
      bridge_.request_snapshot();
      if (const auto now = std::chrono::steady_clock::now(); now >= next_batch) {
        next_batch = now + kBatchPeriod;
        batch();
      }
    }
    lk.lock();
    stop_cv_.wait_for(lk, kSnapshotPeriod, [this] { return stopping_; });
  }
}

std::string EventHub::nodes_event(const std::vector<NodeStatus>& nodes) const {
  nlohmann::json a = nlohmann::json::array();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto b = static_cast<std::size_t>(topo_.node_bus[i]);
    a.push_back(node_json(topo_.node_names[i], topo_.bus_names[b], nodes[i],
                          [this, i](std::uint16_t code) { return catalog_.emcy_text(i, code); }));
  }
  return a.dump();
}

void EventHub::batch() {
  std::vector<std::shared_ptr<Client>> clients;
  {
    std::lock_guard lk(mu_);
    clients = clients_;
  }
  if (clients.empty()) {
    // Nobody listens: only keep the rings from holding stale data (nodes, maps and the clock are
    // read afresh when a client comes, since their versions were not taken).
    CapturedFrame f;
    while (bridge_.frames().pop(f)) {
    }
    while (bridge_.signal_rows().pop(row_)) {
    }
    NodeTransition t;
    while (bridge_.transitions().pop(t)) {
    }
    dropped_seen_ = bridge_.frames_dropped();
    return;
  }
  // Nodes and PDO mappings first: the frames of this batch decode with them.
  bool nodes_changed = false;
  if (const auto v = bridge_.node_version(); v != node_version_) {
    node_version_ = bridge_.nodes(nodes_);
    nodes_event_ = nodes_event(nodes_);
    nodes_changed = true;
  }
  // PDO mappings: copied only when they changed (the copy takes the lock the scheduler's snapshot
  // try_locks).
  const bool maps_changed = bridge_.pdo_version() != pdo_version_;
  if (maps_changed) pdo_version_ = bridge_.pdo_maps(maps_);
  if (maps_changed || nodes_changed) {
    for (auto& d : decoders_) d->update(topo_.node_bus, nodes_, maps_);
  }

  // Frames: the ring drained (even without clients: nothing stale later), the newest
  // kMaxFramesPerBatch decoded once for every client; older ones (full virtual speed carries far
  // more than anyone reads) are counted as dropped, so the trace stays current.
  std::string frames;
  captured_.clear();
  CapturedFrame f;
  while (captured_.size() < bridge_.frames().capacity() && bridge_.frames().pop(f)) captured_.push_back(f);
  std::size_t first = captured_.size() > kMaxFramesPerBatch ? captured_.size() - kMaxFramesPerBatch : 0;
  // Running faster than real time (at this batch and the last: a step while paused keeps every
  // frame), only the frames of the newest stretch of simulated time as long as the wall time
  // since the last batch (what a real-time view of the moment shows): the hub's decoding then
  // costs what it costs at speed 1, not more as the simulation gets faster.
  const auto clock = bridge_.clock();
  const auto wall_now = std::chrono::steady_clock::now();
  const auto span_us = std::max<std::int64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(wall_now - last_batch_wall_).count(),
      std::chrono::duration_cast<std::chrono::microseconds>(kBatchPeriod).count());
  last_batch_wall_ = wall_now;
  if (!clock.realtime && (clock.speed <= 0 || clock.speed > 1) && !clock.paused && !last_clock_.paused &&
      first < captured_.size()) {
    const std::int64_t from = captured_.back().t_us - span_us;
    first = static_cast<std::size_t>(
        std::partition_point(captured_.begin() + static_cast<std::ptrdiff_t>(first), captured_.end(),
                             [from](const CapturedFrame& c) { return c.t_us <= from; }) -
        captured_.begin());
  }
  const std::size_t n = captured_.size() - first;
  nlohmann::json batch = nlohmann::json::array();
  for (std::size_t k = first; !clients.empty() && k < captured_.size(); ++k) {
    const auto& c = captured_[k];
    const auto& bus = topo_.bus_names[c.bus < topo_.bus_names.size() ? c.bus : 0];
    const auto decoded = canopen::decode_frame(c.frame, *decoders_[c.bus < decoders_.size() ? c.bus : 0]);
    batch.push_back(frame_json(c, bus, decoded));
  }
  if (!batch.empty()) frames = batch.dump();
  const auto dropped_total = bridge_.frames_dropped();
  const auto dropped = dropped_total - dropped_seen_ + first;
  dropped_seen_ = dropped_total;

  // Signal rows: each client takes the samples its rate asks for.
  std::vector<std::pair<std::vector<std::int64_t>, std::vector<std::vector<double>>>> per_client(clients.size());
  for (std::size_t i = 0; i < clients.size(); ++i) per_client[i].second.resize(clients[i]->signals_.size());
  while (bridge_.signal_rows().pop(row_)) {
    for (std::size_t i = 0; i < clients.size(); ++i) {
      auto& c = *clients[i];
      if (c.signals_.empty() || row_.t_us < c.next_sample_us_) continue;
      c.next_sample_us_ = row_.t_us + c.period_us_;
      per_client[i].first.push_back(row_.t_us);
      for (std::size_t k = 0; k < c.signals_.size(); ++k) per_client[i].second[k].push_back(row_.values[c.signals_[k]]);
    }
  }

  const bool clock_changed = clock.t_us != last_clock_.t_us || clock.paused != last_clock_.paused ||
                             clock.speed != last_clock_.speed || clock.end_reached != last_clock_.end_reached;
  last_clock_ = clock;
  const std::string clock_event =
      nlohmann::json{{"t_us", clock.t_us}, {"paused", clock.paused}, {"speed", clock.speed}, {"end_reached", clock.end_reached}}
          .dump();

  // State machine transitions: one event each, {"node", ...the entry} (docs/api.md).
  std::string transitions;
  NodeTransition nt;
  while (bridge_.transitions().pop(nt)) {
    auto j = transition_json(nt.transition);
    j["node"] = nt.node < topo_.node_names.size() ? topo_.node_names[nt.node] : std::string();
    append_event(transitions, "transition", j.dump());
  }

  // A restart (POST /api/restart): the page drops what it drew of the old run.
  const auto restarts = bridge_.restarts();
  const bool restarted = restarts != restarts_seen_;
  restarts_seen_ = restarts;
  if (restarted) findings_next_ = 0;

  const bool exercise_changed = refresh_exercise();

  std::vector<std::string> tables(clients.size());
  if (const auto now = std::chrono::steady_clock::now(); now >= next_tables_) {
    next_tables_ = now + kLiveTablePeriod;
    live_tables(clients, tables);
  }

  const auto& names = bridge_.signals();
  for (std::size_t i = 0; i < clients.size(); ++i) {
    auto& c = *clients[i];
    std::string out;
    if (!c.greeted_) {
      const auto node = c.node_ >= 0 ? nlohmann::json(topo_.node_names[static_cast<std::size_t>(c.node_)]) : nlohmann::json();
      append_event(out, "hello", nlohmann::json{{"stream", c.id_}, {"shared", c.shared_}, {"node", node}}.dump());
    }
    if (restarted && c.greeted_) append_event(out, "restart", nlohmann::json{{"restarts", restarts}, {"t_us", clock.t_us}}.dump());
    if (!c.greeted_ || nodes_changed) append_event(out, "nodes", nodes_event_);
    if (!c.greeted_ || clock_changed) append_event(out, "clock", clock_event);
    if ((!c.greeted_ || exercise_changed) && !exercise_event_.empty()) append_event(out, "exercise", exercise_event_);
    c.greeted_ = true;
    if (!per_client[i].first.empty()) {
      nlohmann::json values = nlohmann::json::object();
      for (std::size_t k = 0; k < c.signals_.size(); ++k) values[names[c.signals_[k]].name] = per_client[i].second[k];
      append_event(out, "signals", nlohmann::json{{"t_us", per_client[i].first}, {"values", values}}.dump());
    }
    out += tables[i];
    std::lock_guard lk(c.mu_);
    std::uint64_t lost = dropped;
    if (!frames.empty()) {
      if (c.outbox_.size() + frames.size() > (c.shared_ ? kMaxSharedBacklog : kMaxBacklog)) lost += n;
      else append_event(out, "frames", frames);
    }
    if (lost > 0) append_event(out, "dropped", nlohmann::json{{"frames", lost}}.dump());
    if (!transitions.empty() && c.outbox_.size() + transitions.size() <= kMaxBacklog) out += transitions;
    c.dropped_ += lost;
    if (out.empty()) continue;
    c.outbox_ += out;
    c.cv_.notify_all();
  }
}

}  // namespace control
