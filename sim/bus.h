// A CAN bus inside the simulator: endpoints (emulated nodes, the scripted master, recorders)
// attach to it; every frame one endpoint sends reaches all others, optionally the wire (a
// Transport such as SocketCAN) and the taps (trace writers). Without a transport the bus is the
// in-process virtual bus.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sim/can_frame.h"
#include "sim/ring_buffer.h"
#include "sim/time.h"
#include "sim/transport.h"

namespace sim {

/// Something that receives the frames on a bus.
class FrameReceiver {
 public:
  virtual ~FrameReceiver() = default;
  virtual void on_frame(const CanFrame& frame, Time now) = 0;
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
};

struct BusStats {
  std::uint64_t frames = 0;          ///< frames delivered on this bus (all sources)
  std::uint64_t from_wire = 0;       ///< of which received from the transport
  std::uint64_t dropped_by_filter = 0;
  std::uint64_t delivery_overflow = 0;  ///< ping-pong guard tripped (see deliver())
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

  /// Attaches a receiver; returns its endpoint id (used as `from` when it sends).
  int attach(FrameReceiver* receiver);
  /// Bus-off / disconnected endpoint: neither sends nor receives while offline.
  void set_online(int endpoint, bool online);
  bool online(int endpoint) const;

  /// Queues a frame; it is delivered by the next deliver() (in the same tick).
  void send(int from_endpoint, const CanFrame& frame, Time now);

  /// Delivers queued frames to endpoints, the transport and taps, until no frame is left that
  /// is due at `now`. Replies produced while delivering are delivered in the same call.
  std::size_t deliver(Time now);

  /// Reads everything the transport has received and queues it. Returns the number read.
  std::size_t poll_transport(Time now);

  void set_transport(std::unique_ptr<Transport> transport) { transport_ = std::move(transport); }
  Transport* transport() const { return transport_.get(); }
  void add_tap(FrameTap* tap) { taps_.push_back(tap); }
  void set_filter(FrameFilter* filter) { filter_ = filter; }

  const BusStats& stats() const { return stats_; }

 private:
  struct Pending {
    CanFrame frame;
    int from = kWire;
  };
  struct Delayed {
    Pending pending;
    Time due;
  };
  struct Endpoint {
    FrameReceiver* receiver = nullptr;
    bool online = true;
  };

  void deliver_one(const Pending& p, Time now);

  std::string name_;
  std::vector<Endpoint> endpoints_;
  RingBuffer<Pending> queue_{256};
  std::vector<Delayed> delayed_;  // small: only wire-fault delays
  std::unique_ptr<Transport> transport_;
  std::vector<FrameTap*> taps_;
  FrameFilter* filter_ = nullptr;
  BusStats stats_;
  unsigned bit_rate_kbit_ = 0;
};

}  // namespace sim
