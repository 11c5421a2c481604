// Serves one bus over the socketcand protocol on TCP, so that CAN tools (python-can's
// `socketcand` interface, SavvyCAN, ...) reach the plant without SocketCAN: the bus name is the
// channel a client opens. It is the bus's Transport; the sockets live on the server's own thread.
//
// Every client in raw mode receives every frame of the bus (the plant's and the other clients'),
// stamped with the wall clock; a frame a client sends goes to the bus, where it waits in the
// wire's transmit queue and arbitrates like any node's (on a bit-timed bus), and reaches the other
// clients once the bus has carried it, not the sender (like a CAN_RAW socket). A client has at
// most kClientTxQueue frames on the way; beyond, and when the bus's queue is full, the frame is
// refused with `< error … >` to that client. A message the server cannot use (bad field, unknown or
// unsupported command) is answered with `< error REASON >` and the connection stays; a client
// that breaks the framing (bytes outside `< >`, an overlong message), opens another bus or stops
// reading is closed with a logged reason. Nothing a client does reaches the simulation except
// well-formed frames.
// Its name (the trace's interface column) is the bus name, as on the in-process bus.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "sim/queued_transport.h"
#include "sim/tcp_address.h"

namespace sim {

/// How long a connection may hold a slot without using it (wall clock, milliseconds).
struct SocketcandLimits {
  /// From connect to `< open CHANNEL >`: a connection that never opens the bus is closed.
  int handshake_ms = 5000;
  /// A client in BCM mode (it receives no frames) that sends nothing for this long is closed.
  /// A raw-mode client receives the bus and is never idle; it is closed if it stops reading.
  int bcm_idle_ms = 60000;
};

class SocketcandServer final : public QueuedTransport {
 public:
  static constexpr int kMaxClients = 16;
  /// Output bytes a client may leave unread (beyond the kernel's socket buffers) before it is
  /// dropped as one that never reads: about 20,000 frames, 2.5 s of a saturated 1 Mbit/s bus, so
  /// a client that is merely descheduled for a while is not dropped.
  static constexpr std::size_t kMaxPendingOutput = 1024 * 1024;
  /// After `< ok >` to `< rawmode >`, frames wait this long: python-can reads that `< ok >` with
  /// one recv() and fails if frames arrive in the same segment.
  static constexpr int kRawmodeSettleMs = 200;
  /// Frames one client may have on the way to the bus (handed over, not yet on the wire); more
  /// are refused with `< error frame ID refused: … >`. All clients together then share the bus's
  /// transmit queue for the wire (the bus's `tx_queue`): one client cannot fill it alone.
  static constexpr int kClientTxQueue = 16;
  static_assert(kMaxClients * kClientTxQueue < static_cast<int>(kResultReserve), "results must always fit");

  using Limits = SocketcandLimits;

  /// Listens on `endpoint` for clients of bus `channel`. Port 0 picks a free port (see port()).
  /// A non-loopback address is allowed and logged as a warning. nullptr + `error` on failure.
  static std::unique_ptr<SocketcandServer> open(const std::string& channel, const TcpEndpoint& endpoint,
                                                std::string& error, Limits limits = {});
  ~SocketcandServer() override;

  std::uint16_t port() const { return port_; }
  /// "socketcand 127.0.0.1:29536 channel main": what a master connects to.
  std::string where() const override { return "socketcand " + address_ + " channel " + channel_; }
  /// Clients connected right now, and clients closed for a protocol error or for not reading.
  int client_count() const { return clients_now_.load(std::memory_order_relaxed); }
  /// True from the first client's `< rawmode >` on (it receives the bus's frames from then).
  bool peer_listening() const override { return raw_client_seen_.load(std::memory_order_acquire); }
  std::uint64_t clients_dropped() const { return clients_dropped_.load(std::memory_order_relaxed); }

 private:
  struct Client;
  SocketcandServer(std::string name, std::string channel, int listen_fd, std::uint16_t port, Limits limits);
  std::string address_;  // the listening socket's address, "127.0.0.1:29536"
  /// Closes the clients whose handshake or idle time is up; returns the ms until the next such
  /// deadline (-1: none).
  int expire_clients(std::int64_t now_ms);
  void run();
  void accept_clients();
  void read_client(Client& c);
  void handle(Client& c, std::string_view message);
  void forward_from(Client& from, const CanFrame& frame);
  void broadcast(const CanFrame& frame, const Client* except);
  /// A plant frame for the clients, or what the bus did with a client's frame.
  void on_wire_event(const WireEvent& e);
  void enqueue(Client& c, std::string_view text);
  void flush(Client& c);
  void drop(Client& c, const std::string& reason);
  /// Answers `< error REASON >` and keeps the connection (a well-delimited message it cannot use).
  void refuse(Client& c, const std::string& reason);

  std::string channel_;
  Limits limits_;
  int listen_fd_ = -1;
  std::uint16_t port_ = 0;
  std::vector<std::unique_ptr<Client>> clients_;  // server thread only
  std::uint32_t next_client_id_ = 1;  // server thread only
  std::atomic<int> clients_now_{0};
  std::atomic<bool> raw_client_seen_{false};
  std::atomic<std::uint64_t> clients_dropped_{0};
  std::thread thread_;
};

}  // namespace sim
