// Joins a remote socketcand daemon as a client (e.g. the real can0 of another machine, exposed by
// linux-can/socketcand, or another vplant's SocketcandServer): the bus's frames go out as
// `< send >`, the remote bus's `< frame >`s come in. The connection, the handshake (`< open CH >`,
// `< rawmode >`) and reconnection after a loss run on the transport's own thread. Its name (the
// trace's interface column) is the remote channel.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "sim/queued_transport.h"
#include "sim/socketcand_protocol.h"
#include "sim/tcp_address.h"

namespace sim {

class SocketcandClient final : public QueuedTransport {
 public:
  static constexpr int kReconnectMs = 1000;
  static constexpr int kHandshakeTimeoutMs = 3000;
  /// Bytes of `< send >` text that may wait for a slow server before frames are dropped.
  static constexpr std::size_t kMaxPendingOutput = 64 * 1024;

  /// Resolves `server` now (an unknown host is an error here) and connects in the background,
  /// retrying every kReconnectMs while the server is unreachable. Frames sent before the first
  /// connection wait for it (up to the queue's capacity); frames sent while a lost connection
  /// is being re-established are dropped and counted.
  static std::unique_ptr<SocketcandClient> open(const TcpEndpoint& server, const std::string& channel,
                                                std::string& error);
  ~SocketcandClient() override;

  /// True once `< rawmode >` was acknowledged, until the connection is lost.
  bool connected() const { return connected_.load(std::memory_order_acquire); }
  /// Frames of the bus that could not reach the remote bus (not connected, or it does not read).
  std::uint64_t wire_dropped() const { return wire_dropped_.load(std::memory_order_relaxed); }
  std::string where() const override { return where_; }

 private:
  SocketcandClient(std::string where, std::string channel, ResolvedAddress address);

  void run();
  // The socket, or -1 with `error`; what the server sent after the handshake stays in `in`.
  int connect_and_handshake(socketcand::Splitter& in, std::string& error);
  void stream(int fd, socketcand::Splitter& in);  // until the connection fails or stop
  void discard_outgoing();

  std::string where_;  // for log lines: "socketcand-client 10.0.0.2:29536/can0"
  std::string channel_;
  ResolvedAddress address_;
  std::atomic<bool> connected_{false};
  std::atomic<std::uint64_t> wire_dropped_{0};
  std::thread thread_;
};

}  // namespace sim
