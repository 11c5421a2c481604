// A transport carries a bus's frames to and from the outside world (e.g. a SocketCAN interface).
#pragma once

#include <cstdint>
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
  /// Human-readable endpoint name, e.g. "vcan0" (also the interface field of candump traces).
  virtual std::string_view name() const = 0;
  /// Where a master finds this transport, for start lines and summaries (e.g. "socketcand
  /// 127.0.0.1:29536 channel main"); by default the name.
  virtual std::string where() const { return std::string(name()); }
  /// Whether a peer receives the bus's frames now: a served socketcand bus says so once a client
  /// has put it in raw mode (so a run can power its nodes then and the client sees every boot-up);
  /// an interface is always there. Read between ticks: an atomic load, no system call.
  virtual bool peer_listening() const { return true; }
  /// Non-blocking send. Never blocks the scheduler: a busy link queues and retries in service().
  virtual void send(const CanFrame& frame) = 0;
  /// Non-blocking receive of one frame; false when nothing is pending.
  virtual bool receive(CanFrame& frame) = 0;
  /// receive(), with the transport's tag for the frame: non-zero asks the bus for a wire_result()
  /// (a transport serving several peers attributes and paces their frames by it).
  virtual bool receive_tagged(CanFrame& frame, std::uint32_t& tag) {
    tag = 0;
    return receive(frame);
  }
  /// What became of a frame received with a non-zero tag.
  enum class WireResult : std::uint8_t {
    Delivered,  ///< on the bus: at its end of frame (bit timing), in its tick (ideal)
    Refused,    ///< the bus's transmit queue for the wire was full (or the tick's frame guard tripped)
    Lost,       ///< dropped by a wire fault (FrameFilter)
  };
  virtual void wire_result(std::uint32_t /*tag*/, const CanFrame& /*frame*/, WireResult /*result*/) {}
  /// Retries queued frames and watches the link. Called every tick and after polls.
  virtual void service(Time now) = 0;
  /// File descriptor to wait on for readability (-1 if none).
  virtual int wait_fd() const { return -1; }
  virtual const TransportStats& stats() const = 0;
};

}  // namespace sim
