// Linux SocketCAN raw socket transport: non-blocking, survives the interface going down and up,
// and never blocks the scheduler on a full transmit queue (ENOBUFS is counted and retried).
#pragma once

#include <memory>
#include <string>

#include "sim/ring_buffer.h"
#include "sim/transport.h"

namespace sim {

class SocketCanTransport final : public Transport {
 public:
  /// Opens a raw CAN socket bound to `iface`. On failure returns nullptr and sets `error` to a
  /// message that names the interface (e.g. "CAN interface 'can7' does not exist").
  static std::unique_ptr<SocketCanTransport> open(const std::string& iface, std::string& error);
  /// Adopts an already open, non-blocking datagram socket that carries `struct can_frame`
  /// records (a bound CAN socket, or a socketpair in tests). Takes ownership of `fd`.
  static std::unique_ptr<SocketCanTransport> adopt(std::string name, int fd);
  ~SocketCanTransport() override;

  std::string_view name() const override { return iface_; }
  void send(const CanFrame& frame) override;
  bool receive(CanFrame& frame) override;
  void service(Time now) override;
  int wait_fd() const override { return fd_; }
  const TransportStats& stats() const override { return stats_; }

  bool link_up() const { return link_up_; }

  /// Capacity of the retry queue for frames the kernel refused with ENOBUFS/EAGAIN.
  static constexpr std::size_t kRetryCapacity = 4096;

 private:
  SocketCanTransport(std::string iface, int fd, int ifindex);
  bool write_frame(const CanFrame& frame);  // false: keep for retry
  void mark_down(const char* why);
  void check_link();
  bool rebind();

  std::string iface_;
  int fd_ = -1;
  int ifindex_ = 0;
  bool link_up_ = true;
  Time next_link_check_{};
  RingBuffer<CanFrame> retry_{64};
  TransportStats stats_;
};

/// True if the running kernel can open a CAN raw socket (PF_CAN present).
bool socketcan_available();

}  // namespace sim
