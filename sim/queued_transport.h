// The scheduler side of a transport whose socket I/O runs on its own thread (the socketcand server
// and client). Frames cross between the threads through two bounded lock-free queues; each side
// wakes the other through an eventfd, so the scheduler thread never blocks or touches a socket:
// send() only queues, service() wakes the I/O thread once per tick, receive() only dequeues.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "sim/can_frame.h"
#include "sim/spsc_queue.h"
#include "sim/transport.h"

namespace sim {

class QueuedTransport : public Transport {
 public:
  static constexpr std::size_t kQueueCapacity = 4096;
  /// Slots of the queue to the I/O thread that only wire results may take: the I/O thread bounds
  /// the tagged frames in flight below this, so no result is ever lost to a full queue.
  static constexpr std::size_t kResultReserve = 1024;

  /// What the I/O thread gets from the bus, in bus order.
  struct WireEvent {
    enum class Kind : std::uint8_t { Frame, Delivered, Refused, Lost };
    Kind kind = Kind::Frame;  ///< Frame: the plant's frame for the wire; else the result of a tagged one
    std::uint32_t tag = 0;
    CanFrame frame;
  };

  ~QueuedTransport() override;

  std::string_view name() const override { return name_; }
  void send(const CanFrame& frame) override;
  bool receive(CanFrame& frame) override;
  bool receive_tagged(CanFrame& frame, std::uint32_t& tag) override;
  void wire_result(std::uint32_t tag, const CanFrame& frame, WireResult result) override;
  void service(Time now) override;
  /// Readable when the I/O thread has queued frames for the bus.
  int wait_fd() const override { return to_bus_fd_; }
  const TransportStats& stats() const override { return stats_; }

  /// Frames the I/O thread could not queue for the bus because the scheduler fell behind.
  std::uint64_t rx_dropped() const { return rx_dropped_.load(std::memory_order_relaxed); }

 protected:
  explicit QueuedTransport(std::string name);
  bool eventfds_ok() const { return to_bus_fd_ >= 0 && to_io_fd_ >= 0; }

  // I/O thread side.
  /// Readable when the scheduler has queued frames for the wire (or stop was requested).
  int io_wake_fd() const { return to_io_fd_; }
  void clear_io_wake();
  bool pop_for_wire(WireEvent& event) { return to_wire_.pop(event); }
  /// Queues a frame read from the wire (a non-zero tag asks for its WireEvent result); call
  /// notify_bus() after a batch.
  bool push_to_bus(const CanFrame& frame, std::uint32_t tag = 0);
  void notify_bus();
  bool stop_requested() const { return stop_.load(std::memory_order_acquire); }
  /// Asks the I/O thread to finish (wakes it); the derived destructor joins it.
  void request_stop();
  void count_link_down() { link_down_.fetch_add(1, std::memory_order_relaxed); }

 private:
  std::string name_;
  int to_bus_fd_ = -1;
  int to_io_fd_ = -1;
  struct TaggedFrame {
    CanFrame frame;
    std::uint32_t tag = 0;
  };
  SpscQueue<WireEvent> to_wire_{kQueueCapacity};
  SpscQueue<TaggedFrame> to_bus_{kQueueCapacity};
  bool wake_io_pending_ = false;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint64_t> rx_dropped_{0};
  std::atomic<std::uint64_t> link_down_{0};
  TransportStats stats_;
};

}  // namespace sim
