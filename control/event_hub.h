// The live stream's fan-out (server side): one thread drains what the scheduler captured every
// 50 ms, decodes the frames once, and hands each stream client its server-sent events (frames,
// nodes on change, signals at the client's rate, clock, dropped). A client's backlog is bounded:
// a client that cannot keep up loses frames, counted in a "dropped" event; so do frames the
// scheduler could not capture because the hub was behind, and, faster than real time, those older
// than the newest batch-long stretch of simulated time (decoding costs the same at any speed).
// Every 20 ms it asks the scheduler for a node snapshot (the scheduler
// takes none on its own while the clock runs). The exercise's state goes out as an `exercise`
// event on connect and whenever the selection or a step's done-state changed. New findings of
// the verdict on the master go out as `findings` pages (GET /api/findings gives the earlier ones).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "control/dictionary_catalog.h"
#include "control/exercise_host.h"
#include "control/sim_bridge.h"
#include "devices/canopen/stored_value.h"

namespace control {

struct StreamTopology {
  std::vector<std::string> bus_names;
  std::vector<std::string> node_names;
  std::vector<int> node_bus;
};

class EventHub {
 public:
  class Client {
   public:
    /// Waits up to `timeout` for events; false once the stream is over (hub stopped).
    bool next(std::string& out, std::chrono::milliseconds timeout);

   private:
    friend class EventHub;
    std::mutex mu_;
    std::condition_variable cv_;
    std::string outbox_;
    bool closed_ = false;
    std::vector<std::size_t> signals_;
    std::int64_t period_us_ = 100000;
    std::int64_t next_sample_us_ = 0;
    std::uint64_t dropped_ = 0;  ///< frames this client lost (backlog full)
    bool greeted_ = false;
    std::uint64_t id_ = 0;
    bool shared_ = false;  ///< beyond max_clients: the shared read-only stream, a bounded backlog
    int node_ = -1;        ///< the node whose dictionary this client receives (-1: none)
    bool od_sent_ = false;
    std::vector<canopen::StoredValue> od_last_;  ///< what it was sent, per catalog entry
    std::string faults_sent_;
  };

  /// `exercises`: the plant's exercise (its state is streamed); null for none.
  EventHub(SimBridge& bridge, const DictionaryCatalog& catalog, StreamTopology topology, std::size_t max_clients,
           ExerciseHost* exercises = nullptr);
  ~EventHub();
  EventHub(const EventHub&) = delete;
  EventHub& operator=(const EventHub&) = delete;

  void start();
  void stop();
  /// A new stream for these signals (indices into SimBridge::signals()) at `rate_hz`, carrying
  /// node `node`'s dictionary (-1: none). Beyond max_clients, a shared read-only stream (no
  /// signals, no dictionary; its backlog is small); nullptr beyond kMaxSharedClients more.
  std::shared_ptr<Client> open(std::vector<std::size_t> signals, double rate_hz, int node = -1);
  /// The node stream `id` receives the dictionary of (-1: none); false: no such stream, or a
  /// shared one.
  bool select_node(std::uint64_t id, int node);
  static constexpr std::size_t kMaxSharedClients = 32;
  void close(const std::shared_ptr<Client>& client);
  std::size_t clients() const;

 private:
  void run();
  void batch();
  /// Every kLiveTablePeriod: the selected nodes' dictionaries and the live faults, read between
  /// ticks, as "od" deltas and "faults" events for the clients that want them.
  void live_tables(const std::vector<std::shared_ptr<Client>>& clients, std::vector<std::string>& out);
  std::string nodes_event(const std::vector<NodeStatus>& nodes) const;
  /// True when the exercise's state changed since the last call (exercise_event_ holds it).
  bool refresh_exercise();

  SimBridge& bridge_;
  const DictionaryCatalog& catalog_;
  StreamTopology topo_;
  std::size_t max_clients_;
  ExerciseHost* exercises_;
  std::vector<std::unique_ptr<BusDecoderContext>> decoders_;

  mutable std::mutex mu_;
  std::condition_variable stop_cv_;
  bool stopping_ = false;
  std::vector<std::shared_ptr<Client>> clients_;
  std::thread thread_;

  // Hub thread state.
  std::uint64_t node_version_ = ~0ULL, pdo_version_ = ~0ULL, dropped_seen_ = 0;
  std::uint64_t restarts_seen_ = 0;
  std::size_t findings_next_ = 0;  ///< the first finding of the master monitor not streamed yet
  std::uint64_t exercise_version_ = ~0ULL;
  std::string exercise_event_;  ///< the exercise's state as last sent ("" before the first read)
  std::uint64_t next_id_ = 0;
  std::chrono::steady_clock::time_point next_tables_{};
  std::chrono::steady_clock::time_point last_batch_wall_{};  ///< faster than real time: the frames' window
  std::vector<NodeStatus> nodes_;
  std::vector<CapturedFrame> captured_;  ///< one batch's frames (sized to the ring once)
  std::vector<std::vector<PdoMap>> maps_;
  std::string nodes_event_;
  ClockState last_clock_;
  SignalRow row_;
};

}  // namespace control
