// A transport carries a bus's frames to and from the outside world (e.g. a SocketCAN interface).
#pragma once

#include <string_view>

#include "sim/can_frame.h"
#include "sim/time.h"

namespace sim {

struct TransportStats {
  std::uint64_t tx_frames = 0;     ///< written to the wire
  std::uint64_t rx_frames = 0;     ///< read from the wire
  std::uint64_t tx_busy = 0;       ///< ENOBUFS/EAGAIN on write (frame kept for retry)
  std::uint64_t tx_dropped = 0;    ///< retry queue full or link down: frame lost
  std::uint64_t link_down_events = 0;
};

class Transport {
 public:
  virtual ~Transport() = default;
  /// Human-readable endpoint name, e.g. "vcan0".
  virtual std::string_view name() const = 0;
  /// Non-blocking send. Never blocks the scheduler: a busy link queues and retries in service().
  virtual void send(const CanFrame& frame) = 0;
  /// Non-blocking receive of one frame; false when nothing is pending.
  virtual bool receive(CanFrame& frame) = 0;
  /// Retries queued frames and watches the link. Called every tick and after polls.
  virtual void service(Time now) = 0;
  /// File descriptor to wait on for readability (-1 if none).
  virtual int wait_fd() const { return -1; }
  virtual const TransportStats& stats() const = 0;
};

}  // namespace sim
