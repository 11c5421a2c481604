// A CAN bus inside the simulator: endpoints (emulated nodes, the scripted master, recorders)
// attach to it; every frame one endpoint sends reaches all others, optionally the wire (a
// Transport such as SocketCAN) and the taps (trace writers). Without a transport the bus is the
// in-process virtual bus.
//
// Timing (BusTiming): `Ideal` delivers a frame in the tick it is sent, at zero duration. `Bit`
// gives the in-process bus the wire's time: every frame occupies the bus for its exact bit count
// (can_bit_timing.h) at the bit rate; each endpoint has a FIFO transmit queue of bounded depth;
// when the bus goes idle the queue heads arbitrate (lowest arbitration field wins); a frame is
// delivered at the end of its EOF, stamped with that instant. The bus decides frame starts only
// for instants strictly before the `now` of deliver(), so every frame sent at an instant competes.
//
// Fault confinement (ISO 11898-1) runs in both modes: a transmission the filter destroys
// (FrameFilter::on_transmit) raises an error frame; TEC +8 for the sender, REC +1 for the
// receivers, -1 for each success; error-passive at 128, bus-off above TEC 255 (queue flushed,
// neither sending nor receiving), back to error-active after 128 sequences of 11 recessive bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "sim/can_bit_timing.h"
#include "sim/can_frame.h"
#include "sim/ring_buffer.h"
#include "sim/time.h"
#include "sim/transport.h"

namespace sim {

/// ISO 11898-1 fault confinement state of one CAN controller.
enum class ErrorState : std::uint8_t { Active, Passive, BusOff };

enum class BusTiming : std::uint8_t { Ideal, Bit };

/// Something that receives the frames on a bus.
class FrameReceiver {
 public:
  virtual ~FrameReceiver() = default;
  virtual void on_frame(const CanFrame& frame, Time now) = 0;
  /// The endpoint's own controller changed its fault confinement state (see Bus).
  virtual void on_error_state(ErrorState /*state*/, Time /*now*/) {}
};

/// Observes every frame that crosses the bus exactly once (trace writers, counters, checks).
class FrameTap {
 public:
  virtual ~FrameTap() = default;
  /// `wire_name` is the interface name when the bus has a transport, else the bus name.
  virtual void on_bus_frame(std::string_view wire_name, const CanFrame& frame, Time now) = 0;
};

/// Wire-level fault injection: may drop, delay or alter a frame as it is sent.
class FrameFilter {
 public:
  struct Verdict {
    bool drop = false;
    Duration delay{0};
  };
  virtual ~FrameFilter() = default;
  virtual Verdict on_send(CanFrame& frame, int from_endpoint, Time now) = 0;
  /// Called for every transmission attempt (retransmissions too); true = a bit error destroys
  /// this attempt (error frame, counters, automatic retransmission).
  virtual bool on_transmit(const CanFrame& /*frame*/, int /*from_endpoint*/, Time /*start*/) { return false; }
};

struct BusStats {
  std::uint64_t frames = 0;          ///< frames delivered on this bus (all sources)
  std::uint64_t from_wire = 0;       ///< of which received from the transport
  std::uint64_t dropped_by_filter = 0;
  std::uint64_t delivery_overflow = 0;  ///< ping-pong guard tripped (see deliver())
  std::uint64_t tx_queue_overflow = 0;  ///< Bit timing: frames refused by a full transmit queue
  std::uint64_t error_frames = 0;       ///< transmissions destroyed by a bit error
  std::uint64_t busy_bits = 0;          ///< bits the frames and error frames occupied the bus
};

/// Traffic of one identifier (frames delivered and the bits they occupied).
struct IdTraffic {
  std::uint32_t id = 0;
  bool extended = false;
  std::uint64_t frames = 0;
  std::uint64_t bits = 0;
};

/// The fault confinement counters of one endpoint.
struct ErrorCounters {
  unsigned tec = 0;
  unsigned rec = 0;
  ErrorState state = ErrorState::Active;
  std::uint64_t tx_queue_overflow = 0;
  std::uint64_t bus_off_events = 0;
};

class Bus {
 public:
  static constexpr int kWire = -1;

  explicit Bus(std::string name);
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  const std::string& name() const { return name_; }
  /// The wire's bit rate in kbit/s (0 = unspecified: every node is assumed to match). A node
  /// configured for another rate can neither send nor receive (see canopen::Node).
  void set_bit_rate_kbit(unsigned kbit) { bit_rate_kbit_ = kbit; }
  unsigned bit_rate_kbit() const { return bit_rate_kbit_; }

  /// Bit timing at `bit_rate` bit/s, or the ideal zero-time bus (the default).
  void set_timing(BusTiming timing, std::uint32_t bit_rate = 500000);
  BusTiming timing() const { return timing_; }
  /// The rate frames are timed (and bus load computed) at, bit/s.
  std::uint32_t timing_bit_rate() const { return timing_rate_; }
  /// Depth of each endpoint's transmit queue (Bit timing); a frame sent to a full queue is
  /// dropped and counted. Default kDefaultTxQueue.
  void set_tx_queue_depth(std::size_t depth) {
    tx_depth_ = depth == 0 ? 1 : depth;
    unsettle();
  }
  static constexpr std::size_t kDefaultTxQueue = 32;
  /// The sliding window of load().
  static constexpr int kLoadWindowMs = 100;

  /// Attaches a receiver; returns its endpoint id (used as `from` when it sends).
  int attach(FrameReceiver* receiver);
  /// Bus-off / disconnected endpoint: neither sends nor receives while offline.
  void set_online(int endpoint, bool online);
  bool online(int endpoint) const;

  /// Queues a frame; it is delivered by the next deliver() (in the same tick).
  void send(int from_endpoint, const CanFrame& frame, Time now);

  /// Delivers queued frames to endpoints, the transport and taps, until no frame is left that
  /// is due at `now`. Replies produced while delivering are delivered in the same call.
  std::size_t deliver(Time now) {
    if (settled(now)) return 0;
    if (quiet_at(now.time_since_epoch().count() * 1000)) {
      settled_at_ = now;
      return 0;
    }
    return deliver_due(now);
  }
  /// True when deliver(now) is known to have nothing to do: it found nothing at this instant and
  /// nothing was sent or changed since. One compare; the scheduler asks it after every component.
  bool settled(Time now) const { return now == settled_at_; }

  /// Reads everything the transport has received and queues it. Returns the number read.
  std::size_t poll_transport(Time now);

  void set_transport(std::unique_ptr<Transport> transport) {
    transport_ = std::move(transport);
    unsettle();
  }
  Transport* transport() const { return transport_.get(); }
  void add_tap(FrameTap* tap) { taps_.push_back(tap); }
  /// While taps see a frame: the endpoint that sent it (kWire: the transport), so a tap can tell
  /// an emulated node's frame from the master's.
  int tap_sender() const { return tap_sender_; }
  void set_filter(FrameFilter* filter) { filter_ = filter; }

  const BusStats& stats() const { return stats_; }
  /// Fraction of the last kLoadWindowMs whole milliseconds before the last deliver() that frames
  /// and error frames occupied the bus (a frame counts from its start, intermission included).
  double load() const;
  /// Busy time / elapsed time since the start of the run, at the last deliver().
  double mean_load() const;
  /// Per identifier, in first-seen order (standard identifiers, then extended ones).
  std::vector<IdTraffic> traffic() const;
  const ErrorCounters& counters(int endpoint) const;
  std::size_t endpoint_count() const { return endpoints_.size(); }
  /// The frame on the wire or waiting in a queue (Bit timing): frames not yet delivered.
  std::size_t pending_frames() const;

 private:
  struct Pending {
    CanFrame frame;
    int from = kWire;
  };
  struct Queued {
    CanFrame frame;
    std::int64_t ready_ns = 0;  ///< sent at
  };
  struct InFlight {
    bool active = false;
    int from = kWire;
    CanFrame frame;
    bool error = false;
    std::int64_t start_ns = 0;
    std::int64_t deliver_ns = 0;  ///< end of EOF (or of the error frame)
    std::int64_t end_ns = 0;      ///< bus free again (after intermission)
    unsigned bits = 0;
    bool head = false;  ///< still the head of the sender's queue (not cleared since it started)
  };
  struct Delayed {
    Pending pending;
    Time due;
    std::uint32_t wire_tag = 0;  ///< the transport's tag of a wire frame (see Transport::wire_result)
  };
  // The wire's frames waiting in queue_ (ideal) or wire_.tx (bit timing), in the same order,
  // with their transport tags: the transport learns what became of each (wire_result).
  struct WireTag {
    std::uint32_t tag = 0;
    CanFrame frame;
  };
  struct Endpoint {
    FrameReceiver* receiver = nullptr;
    bool online = true;
    RingBuffer<Queued> tx{8};
    std::int64_t suspend_until_ns = 0;  ///< error-passive: suspend transmission after sending
    // The queue's head as arbitration sees it (valid while tx is not empty): when it may start,
    // max(its ready_ns, suspend_until_ns), and its arbitration_key().
    std::int64_t head_ready_ns = 0;
    std::uint64_t head_key = 0;
    bool receives = false;  ///< takes frames: a receiver, online, not bus-off (see refresh_receiver)
    std::int64_t recessive_ns = 0;      ///< bus-off: idle time not yet counted as 11-bit sequences
    unsigned recovery_sequences = 0;    ///< bus-off: sequences of 11 recessive bits seen
    ErrorCounters counters;
  };

  /// True when deliver() at `now_ns` has nothing to do: time has not moved since the last call,
  /// no frame is due, the idle time is counted and there is no transport to service. The
  /// scheduler calls deliver() after every component; most calls end here.
  bool quiet_at(std::int64_t now_ns) const {
    if (now_ns > now_ns_ || transport_ || !delayed_.empty()) return false;
    if (timing_ == BusTiming::Ideal) {
      if (!queue_.empty()) return false;
    } else if (in_flight_.active ? in_flight_.deliver_ns <= now_ns : std::max(idle_ns_, ready_floor_ns_) < now_ns) {
      return false;
    }
    return in_flight_.active || now_ns <= std::max(idle_ns_, idle_accounted_ns_);
  }
  std::size_t deliver_due(Time now);
  void send_tagged(int from_endpoint, const CanFrame& frame, Time now, std::uint32_t wire_tag);
  // A wire frame left the queues: tell the transport (tags 0 are not reported).
  void wire_done(Transport::WireResult result);
  void wire_refused(std::uint32_t tag, const CanFrame& frame) {
    if (tag != 0 && transport_) transport_->wire_result(tag, frame, Transport::WireResult::Refused);
  }
  // Every change that could give deliver() work forgets the settled instant.
  void unsettle() { settled_at_ = kNeverSettled; }
  static constexpr Time kNeverSettled = Time{Duration{std::numeric_limits<Duration::rep>::min()}};
  void deliver_one(const Pending& p, Time now);
  void deliver_timed(Time now, std::size_t& n);
  bool start_next(std::int64_t now_ns);
  // Transmit queues (Bit timing); they keep tx_pending_ and ready_floor_ns_ up to date.
  void tx_push(int from, const Queued& q);
  void tx_pop(int from);
  void tx_clear(int index);
  // Endpoint::receives: a receiver, online, not bus-off; rx_list_ lists them.
  void refresh_receiver(int index);
  // Sets the head's arbitration fields from the queue's front and suspend_until_ns.
  static void refresh_head(Endpoint& ep);
  void complete(Time now);
  void deliver_to_receivers(const CanFrame& frame, int from, Time at);
  void release_delayed(Time now);
  Endpoint* endpoint_of(int from) { return from == kWire ? &wire_ : &endpoints_[static_cast<std::size_t>(from)]; }
  bool participates(int index) const;
  // Fault confinement.
  void transmit_error(int from, Time at);
  void transmit_success(int from, Time at);
  void receive_result(int from, bool error, Time at);
  void update_state(int index, Time at);
  void recessive_sequences(unsigned count, Time at);
  void add_recovery(int index, unsigned sequences, Time at);
  void idle_until(std::int64_t until_ns, Time at);
  void count_idle(std::int64_t from_ns, std::int64_t until_ns, Time at);
  void account(const CanFrame* frame, unsigned bits, std::int64_t start_ns);
  void notify(int index, ErrorState state, Time at);
  std::int64_t bit_ns() const { return bit_ns_; }

  std::string name_;
  std::vector<Endpoint> endpoints_;
  RingBuffer<Pending> queue_{256};
  std::vector<Delayed> delayed_;  // small: only wire-fault delays
  RingBuffer<WireTag> wire_tags_{8};
  std::unique_ptr<Transport> transport_;
  std::vector<FrameTap*> taps_;
  int tap_sender_ = kWire;
  FrameFilter* filter_ = nullptr;
  BusStats stats_;
  unsigned bit_rate_kbit_ = 0;

  BusTiming timing_ = BusTiming::Ideal;
  std::uint32_t timing_rate_ = 500000;
  std::int64_t bit_ns_ = 1000000000LL / 500000;
  std::size_t tx_depth_ = kDefaultTxQueue;
  Endpoint wire_;                      // the transport's frames (Bit timing)
  InFlight in_flight_;
  // Endpoints whose transmit queue holds a frame, a bit each (the wire's queue is wire_.tx), so
  // arbitration looks only at queues with something in them.
  std::vector<std::uint64_t> tx_pending_;
  // The endpoints that take frames, in endpoint order (rebuilt when one starts or stops taking
  // them, within the capacity attach() reserved); rx_version_ counts the rebuilds.
  struct Rx {
    FrameReceiver* receiver;
    int index;
  };
  std::vector<Rx> rx_list_;
  std::uint64_t rx_version_ = 0;
  // Load window: the bucket the last frame ended in, [load_lo_ns_, load_lo_ns_ + 1 ms).
  std::int64_t load_lo_ns_ = std::numeric_limits<std::int64_t>::min() / 2;  // none yet
  std::size_t load_index_ = 0;
  FrameBitsCache bits_cache_;
  // No queue head is ready before this instant (a lower bound: exact after start_next() scanned
  // the queues, lowered when a head appears): deliver() skips the queues while it is >= now.
  std::int64_t ready_floor_ns_ = std::numeric_limits<std::int64_t>::max();
  int bus_off_count_ = 0;              // endpoints in BusOff (only they count recessive bits)
  int rec_nonzero_count_ = 0;          // endpoints whose REC is above 0 (a success lowers it)
  std::int64_t idle_ns_ = 0;           // the bus is free from here
  std::int64_t idle_accounted_ns_ = 0; // idle time counted for bus-off recovery up to here
  std::int64_t now_ns_ = 0;            // the last deliver()
  Time settled_at_ = kNeverSettled;    // deliver() at this instant has nothing to do (see settled())
  std::uint64_t busy_ns_ = 0;
  // Load window: busy nanoseconds per millisecond. A frame is counted when it starts, so buckets
  // ahead of now are written too (the longest frame at 10 kbit/s lasts 16 ms).
  static constexpr int kLoadBuckets = kLoadWindowMs + 32;
  struct LoadBucket {
    std::int64_t ms = -1;
    std::int64_t busy_ns = 0;
  };
  std::vector<LoadBucket> load_;
  std::vector<IdTraffic> std_traffic_;  // 2048, indexed by identifier
  std::vector<IdTraffic> ext_traffic_;  // first seen order
  std::vector<std::uint16_t> std_order_;
  ErrorCounters wire_counters_;
};

}  // namespace sim
