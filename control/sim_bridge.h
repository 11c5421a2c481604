// The scheduler's side of the live control plane. It is the run's RunExtension: between ticks,
// on the scheduler's thread, it runs the commands the server threads queued (SDO, NMT, frames,
// faults, inputs, clock), gates virtual time (pause, step, run N ms, pacing), and publishes what
// the server threads read: node status snapshots, captured frames and signal samples (lock-free
// rings, only while a stream client listens), PDO mappings.
//
// What it costs the scheduler per tick while the clock runs: one relaxed load of the "wanted"
// word (commands queued, a snapshot asked for), one of the listener count, and with a listener
// the rings' publish and a time compare for sampling. Node snapshots are taken when the event
// hub asks (at most 50 times a wall second) and whenever the clock stands, not every tick. A
// captured frame is a plain copy into a preallocated ring. It never blocks while the clock runs
// (try_lock; a full ring drops and counts), makes no system call and allocates nothing per tick
// or frame (tests/control/bridge_allocation_test.cpp).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "control/live_state.h"
#include "control/spsc_ring.h"
#include "engine/running/run_extension.h"
#include "engine/running/sdo_client.h"
#include "engine/running/sync_producer.h"
#include "sim/bus.h"
#include "sim/display_unit.h"

namespace control {

/// Virtual-time speeds a client may ask for: 0 (as fast as possible) or kMinSpeed..kMaxSpeed × wall
/// clock. Below kMinSpeed a tick would take longer than a wall second per simulated millisecond
/// tick, which no one watches: refused rather than honoured badly.
constexpr double kMinSpeed = 0.001;
constexpr double kMaxSpeed = 1000;
/// Commands waiting for the next tick boundary; post() refuses more (the HTTP workers, which
/// wait for their command, never queue more than a few: the bound is for a runaway poster).
constexpr std::size_t kMaxQueuedCommands = 256;

struct ClockOptions {
  bool start_paused = true;  ///< virtual time: the run waits at t = 0 for the dashboard
  double speed = 1.0;        ///< virtual time: × wall clock while running; 0 = as fast as possible
};

/// A plant signal the stream can sample: a port of the plant or of a node.
struct SignalInfo {
  std::string name;  ///< "cyl.position", "dsv.solenoid_a_current"
  std::string unit;  ///< SI
  const double* value = nullptr;
  sim::DisplayUnit display{};  ///< how to show it, as the port's owner says
};

struct SignalRow {
  std::int64_t t_us = 0;
  std::vector<double> values;  ///< in SimBridge::signals() order
};

struct SdoOutcome {
  enum class Kind { Done, Aborted, Failed, Busy } kind = Kind::Done;
  std::vector<std::uint8_t> data;  ///< upload: the bytes read
  std::uint32_t abort_code = 0;
  std::string error;  ///< Failed / Busy: why
};

struct ClockState {
  bool realtime = false;
  std::int64_t t_us = 0;
  std::int64_t tick_us = 1000;
  bool paused = false;
  double speed = 1.0;
  std::uint64_t run_ticks_left = 0;
  bool end_reached = false;
};

class SimBridge final : public scenario::RunExtension {
 public:
  /// Runs on the scheduler's thread between ticks, with the run.
  using Command = std::function<void(const scenario::RunContext&)>;

  explicit SimBridge(ClockOptions clock);
  ~SimBridge() override;

  // scenario::RunExtension (scheduler thread). attach again after a restart: the new run's
  // context; the clock keeps its pause and speed, what belonged to the old run is dropped.
  void attach(const scenario::RunContext& context) override;
  bool before_tick(bool end_reached) override;
  void detach() override;
  bool wants_restart() override { return restart_pending_; }

  /// Asks the runner to rebuild the scenario at t = 0 at the next tick boundary (POST
  /// /api/restart); the future holds true once the new run is attached, false if the run ended.
  std::future<bool> request_restart();
  /// Restarts so far (the stream tells its clients).
  std::uint64_t restarts() const { return restarts_.load(); }

  // ---- any thread ---------------------------------------------------------------------------
  enum class Posted { Queued, Full, Ended };
  /// Queues a command for the next tick boundary: Full at kMaxQueuedCommands, Ended once the
  /// run has ended.
  Posted try_post(Command command);
  bool post(Command command) { return try_post(std::move(command)) == Posted::Queued; }
  /// Runs `f` between ticks and returns its result; nullopt when the run does not answer in time.
  template <typename R>
  std::optional<R> call(std::function<R(const scenario::RunContext&)> f, std::chrono::milliseconds timeout,
                        Posted* posted = nullptr) {
    auto promise = std::make_shared<std::promise<R>>();
    auto future = promise->get_future();
    const auto p = try_post([promise, f = std::move(f)](const scenario::RunContext& c) { promise->set_value(f(c)); });
    if (posted) *posted = p;
    if (p != Posted::Queued) return std::nullopt;
    if (future.wait_for(timeout) != std::future_status::ready) return std::nullopt;
    try {
      return future.get();
    } catch (const std::future_error&) {  // the run ended before the command ran
      return std::nullopt;
    }
  }
  /// An SDO transfer over node `node`'s bus (upload when `data` is empty and `upload`).
  std::future<SdoOutcome> sdo(std::size_t node, bool upload, std::uint16_t index, std::uint8_t sub,
                              std::vector<std::uint8_t> data);

  bool attached() const { return attached_.load(); }
  bool finished() const { return finished_.load(); }
  ClockState clock() const;
  /// Virtual time only (the caller checks); they take effect at the next tick boundary.
  bool pause();
  bool resume(std::optional<double> speed);
  /// Runs `ticks` ticks (at the current speed), then stays paused.
  bool run_ticks(std::uint64_t ticks);

  /// Asks for a node snapshot at the next tick boundary (the event hub, at most 50 Hz). Any thread.
  void request_snapshot() { wanted_.fetch_or(kWantSnapshot, std::memory_order_relaxed); }
  /// Node status as last published (scenario order); returns its version (changes on change).
  std::uint64_t nodes(std::vector<NodeStatus>& out) const;
  std::uint64_t node_version() const { return node_version_.load(); }
  /// PDO mappings per node as last published; returns their version.
  std::uint64_t pdo_maps(std::vector<std::vector<PdoMap>>& out) const;
  std::uint64_t pdo_version() const { return pdo_version_.load(); }

  /// Frame and signal capture runs while a stream listens (counted: several streams may).
  void add_listener();
  void remove_listener();
  SpscRing<CapturedFrame>& frames() { return frames_; }
  /// Frames not captured because the ring was full (the hub decodes fewer than the bus carries,
  /// e.g. at full virtual speed): a running total.
  std::uint64_t frames_dropped() const { return frames_dropped_.load(std::memory_order_relaxed); }
  SpscRing<SignalRow>& signal_rows() { return *signal_rows_; }
  /// The devices' new transitions, taken with each node snapshot while a stream listens (a full
  /// ring drops them: GET /api/nodes/{n}/transitions still has them).
  SpscRing<NodeTransition>& transitions() { return transitions_; }
  /// Fixed at attach.
  const std::vector<SignalInfo>& signals() const { return signals_; }
  std::int64_t signal_period_us() const { return signal_period_us_; }

  /// Sends a frame from the control plane's endpoint on bus `bus` (scheduler thread: commands);
  /// false when the bus refused it (its transmit queue for this endpoint is full).
  bool send_frame(std::size_t bus, const sim::CanFrame& frame);

  /// The control plane's SYNC producer on bus `bus` (POST /api/sync), run before every tick while
  /// one is on; period 0 stops it (scheduler thread: commands). Independent of the script's.
  void set_sync(std::size_t bus, sim::Duration period, std::uint8_t counter_overflow);
  const scenario::SyncProducer& sync(std::size_t bus) const { return sync_[bus]; }

  /// Fault ids: live faults applied by the dashboard (scheduler thread only).
  struct LiveFault {
    int id = 0;
    std::string summary;
    std::int64_t since_us = 0;
    std::int64_t until_us = -1;  ///< when its `for:` ends it; -1: until DELETE
    std::function<void(sim::Time)> clear;
    std::function<bool()> over;  ///< true once it ended by itself (a power-off whose node has power again)
    /// Still in force at `now_us`: its `for:` has not run out and it has not ended by itself.
    bool active(std::int64_t now_us) const { return (until_us < 0 || until_us > now_us) && !(over && over()); }
  };
  /// The live faults still in force at `now_us` (the ended ones are dropped first).
  std::vector<LiveFault>& live_faults(std::int64_t now_us) {
    std::erase_if(live_faults_, [now_us](const LiveFault& f) { return !f.active(now_us); });
    return live_faults_;
  }
  int next_fault_id() { return ++fault_ids_; }

 private:
  class BusTap;
  class BusMaster;
  struct SdoJob;

  void service();
  bool drain_commands();
  void publish_nodes(std::int64_t now_us, bool wait);
  void capture_transitions();
  void publish_capture();
  BusMaster& master(std::size_t bus);
  void refresh_pdo_maps();
  void sample_signals(std::int64_t now_us);
  void finish_sdo_jobs();
  bool sdo_in_flight() const;
  void pace();
  void wait_for_work(std::chrono::steady_clock::time_point until);
  void record_emcy(std::size_t bus, const sim::CanFrame& f, sim::Time now);

  ClockOptions options_;
  std::unique_ptr<scenario::RunContext> ctx_;
  // Read by server threads (clock()): a copy, since the scheduler dies with the run.
  std::atomic<std::int64_t> tick_us_{1000};
  bool realtime_ = false;
  std::atomic<bool> attached_{false}, finished_{false};

  // What the server threads want from the scheduler: read once per tick (relaxed).
  static constexpr unsigned kWantCommands = 1, kWantSnapshot = 2;
  std::atomic<unsigned> wanted_{0};

  // Commands.
  mutable std::mutex queue_mu_;
  std::condition_variable wake_;
  std::vector<Command> queue_, running_;

  // Clock: changed only by commands (scheduler thread), read by clock() from any thread.
  std::atomic<bool> paused_{false};
  std::atomic<double> speed_{1.0};
  std::atomic<std::uint64_t> budget_{0};  ///< ticks to run while paused (step, run N ms)
  bool end_seen_ = false;
  std::atomic<bool> end_reached_{false};
  std::atomic<std::int64_t> now_us_{0};
  std::chrono::steady_clock::time_point anchor_wall_;
  std::int64_t anchor_sim_us_ = 0;
  bool anchor_valid_ = false;

  // Node status.
  std::vector<NodeStatus> work_, last_;
  mutable std::mutex pub_mu_;
  std::vector<NodeStatus> published_;
  std::atomic<std::uint64_t> node_version_{0};
  bool dirty_ = false;
  std::vector<std::array<int, 128>> node_by_id_;  ///< per bus: node-ID → node index (-1)

  // PDO maps.
  std::vector<std::vector<PdoMap>> pdo_work_, pdo_published_;
  std::atomic<std::uint64_t> pdo_version_{0};
  bool pdo_dirty_ = false;

  // Capture.
  std::atomic<int> listeners_{0};
  bool capturing_ = false;  ///< listeners_ > 0 as of this tick (read per frame: scheduler only)
  SpscRing<CapturedFrame> frames_{16384};
  std::uint64_t dropped_ = 0;  ///< scheduler's count, published to frames_dropped_ per tick
  std::atomic<std::uint64_t> frames_dropped_{0};
  SpscRing<NodeTransition> transitions_{1024};
  std::vector<std::uint64_t> transition_seen_;  ///< per node: the last seq taken
  std::vector<SignalInfo> signals_;
  std::unique_ptr<SpscRing<SignalRow>> signal_rows_;
  std::int64_t signal_period_us_ = 20000;
  std::int64_t next_sample_us_ = 0;

  std::vector<std::unique_ptr<BusTap>> taps_;
  /// The control plane's endpoints, attached to a bus on first use (an endpoint costs the bus
  /// work per frame, so a dashboard that only watches adds none).
  std::vector<std::unique_ptr<BusMaster>> masters_;
  std::vector<std::unique_ptr<SdoJob>> sdo_jobs_;  ///< at most one per bus
  int sdo_active_ = 0;

  std::vector<LiveFault> live_faults_;
  int fault_ids_ = 0;

  // Restart (scheduler thread, but for restarts_).
  bool restart_pending_ = false;
  std::vector<std::shared_ptr<std::promise<bool>>> restart_waiters_;
  std::atomic<std::uint64_t> restarts_{0};
  void forget_run();

  std::vector<scenario::SyncProducer> sync_;  ///< per bus
  bool sync_on_ = false;                      ///< any of them has a period
  void produce_sync();
  bool tick_goes_ahead();  ///< before_tick's answer when the tick runs (unless stopping)
};

}  // namespace control
