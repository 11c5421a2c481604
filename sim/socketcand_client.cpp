#include "sim/socketcand_client.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "sim/log.h"
#include "sim/socketcand_protocol.h"

namespace sim {

namespace {

std::int64_t monotonic_ms() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
}

bool send_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::send(fd, text.data(), text.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// Reads until the splitter yields one message or `deadline_ms` passes (handshake only).
bool read_message(int fd, socketcand::Splitter& in, socketcand::Message& m, std::int64_t deadline_ms,
                  std::string& error) {
  for (;;) {
    std::string_view text;
    const auto r = in.next(text, error);
    if (r == socketcand::Splitter::Result::Error) return false;
    if (r == socketcand::Splitter::Result::Message) return socketcand::parse(text, m, error);
    const std::int64_t left = deadline_ms - monotonic_ms();
    pollfd p{fd, POLLIN, 0};
    if (left <= 0 || ::poll(&p, 1, static_cast<int>(left)) <= 0) {
      error = "no answer from the server";
      return false;
    }
    char buf[256];
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n <= 0) {
      error = n == 0 ? "the server closed the connection" : std::strerror(errno);
      return false;
    }
    std::string_view rest(buf, static_cast<std::size_t>(n));
    // The handshake is short: whatever does not fit now is an overlong message.
    if (in.feed(rest) != rest.size()) {
      error = "overlong answer from the server";
      return false;
    }
  }
}

bool expect(int fd, socketcand::Splitter& in, socketcand::Kind kind, const char* what, std::int64_t deadline_ms,
            std::string& error) {
  socketcand::Message m;
  if (!read_message(fd, in, m, deadline_ms, error)) return false;
  if (m.kind == kind) return true;
  error = m.kind == socketcand::Kind::Error ? "the server answered '" + std::string(m.text) + "'"
                                            : std::string("expected ") + what + " from the server";
  return false;
}

}  // namespace

std::unique_ptr<SocketcandClient> SocketcandClient::open(const TcpEndpoint& server, const std::string& channel,
                                                         std::string& error) {
  if (channel.empty() || channel.size() > 64 || channel.find_first_of(" <>\t") != std::string::npos) {
    error = "socketcand client: '" + channel + "' is not a channel name";
    return nullptr;
  }
  const auto addr = resolve_tcp(server, error);
  if (!addr) return nullptr;
  const std::string where =
      "socketcand-client " + to_string(reinterpret_cast<const sockaddr*>(&addr->addr), addr->len) + "/" + channel;
  std::unique_ptr<SocketcandClient> client(new SocketcandClient(where, channel, *addr));
  if (!client->eventfds_ok()) {
    error = std::string("socketcand client: eventfd: ") + std::strerror(errno);
    return nullptr;
  }
  client->thread_ = std::thread([c = client.get()] { c->run(); });
  return client;
}

SocketcandClient::SocketcandClient(std::string where, std::string channel, ResolvedAddress address)
    : QueuedTransport(channel), where_(std::move(where)), channel_(std::move(channel)), address_(address) {}

SocketcandClient::~SocketcandClient() {
  request_stop();
  if (thread_.joinable()) thread_.join();
}

void SocketcandClient::run() {
  std::string last_error;
  bool ever_connected = false;
  while (!stop_requested()) {
    std::string error;
    socketcand::Splitter in;
    const int fd = connect_and_handshake(in, error);
    if (fd >= 0) {
      log(LogLevel::Info, "{}: connected", where_);
      last_error.clear();
      ever_connected = true;
      connected_.store(true, std::memory_order_release);
      stream(fd, in);
      connected_.store(false, std::memory_order_release);
      ::close(fd);
      if (stop_requested()) break;
      count_link_down();
    } else if (error != last_error) {
      // Said once per distinct reason, not every retry.
      log(LogLevel::Warn, "{}: {}; retrying every {} ms", where_, error, kReconnectMs);
      last_error = error;
    }
    // Wait before the next attempt; wake early on stop. Until the first connection the bus's
    // frames (its nodes' boot-ups) wait in the bounded queue; after a loss they are stale and
    // dropped.
    const std::int64_t until = monotonic_ms() + kReconnectMs;
    while (!stop_requested()) {
      const std::int64_t left = until - monotonic_ms();
      if (left <= 0) break;
      pollfd p{io_wake_fd(), POLLIN, 0};
      ::poll(&p, 1, static_cast<int>(left));
      clear_io_wake();
      if (ever_connected) discard_outgoing();
    }
  }
}

int SocketcandClient::connect_and_handshake(socketcand::Splitter& in, std::string& error) {
  const int fd = ::socket(address_.family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    error = std::string("socket: ") + std::strerror(errno);
    return -1;
  }
  const std::int64_t deadline = monotonic_ms() + kHandshakeTimeoutMs;
  bool ok = true;
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address_.addr), address_.len) != 0) {
    ok = errno == EINPROGRESS;
    if (ok) {
      pollfd p{fd, POLLOUT, 0};
      int so_error = 0;
      socklen_t len = sizeof so_error;
      ok = ::poll(&p, 1, kHandshakeTimeoutMs) == 1 && ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &so_error, &len) == 0 &&
           so_error == 0;
      if (!ok) errno = so_error != 0 ? so_error : ETIMEDOUT;
    }
  }
  if (!ok) {
    error = std::string("cannot connect: ") + std::strerror(errno);
    ::close(fd);
    return -1;
  }
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  using socketcand::Kind;
  ok = expect(fd, in, Kind::Hi, "'< hi >'", deadline, error) && send_all(fd, "< open " + channel_ + " >") &&
       expect(fd, in, Kind::Ok, "'< ok >' to '< open >'", deadline, error) && send_all(fd, "< rawmode >") &&
       expect(fd, in, Kind::Ok, "'< ok >' to '< rawmode >'", deadline, error);
  if (!ok) {
    if (error.empty()) error = "the connection failed during the handshake";
    ::close(fd);
    return -1;
  }
  return fd;
}

void SocketcandClient::stream(int fd, socketcand::Splitter& in) {
  std::string out;
  out.reserve(kMaxPendingOutput);
  std::string reason;
  // Handles every complete message in `in`; frames go to the bus.
  const auto drain = [&] {
    bool pushed = false;
    std::string_view text;
    std::string error;
    for (;;) {
      const auto r = in.next(text, error);
      if (r == socketcand::Splitter::Result::NeedMore) break;
      socketcand::Message m;
      if (r == socketcand::Splitter::Result::Error || !socketcand::parse(text, m, error)) {
        reason = "protocol error from the server: " + error;
        break;
      }
      if (m.kind == socketcand::Kind::Frame) {
        push_to_bus(m.frame);
        pushed = true;
      } else if (m.kind == socketcand::Kind::Error) {
        log(LogLevel::Warn, "{}: the server reports '{}'", where_, m.text);
      }
    }
    if (pushed) notify_bus();
  };
  drain();
  char buf[4096];
  while (!stop_requested() && reason.empty()) {
    // What the bus queued (also what waited for this connection); a frame queued after this
    // leaves io_wake_fd readable.
    WireEvent e;  // only the bus's frames: this transport tags nothing it receives
    char text[socketcand::kFormatMax];
    while (pop_for_wire(e)) {
      const std::size_t n = socketcand::format_send(e.frame, text);
      if (out.size() + n > kMaxPendingOutput) {
        wire_dropped_.fetch_add(1, std::memory_order_relaxed);
        continue;
      }
      out.append(text, n);
    }
    pollfd fds[2] = {{io_wake_fd(), POLLIN, 0}, {fd, static_cast<short>(POLLIN | (out.empty() ? 0 : POLLOUT)), 0}};
    if (::poll(fds, 2, -1) < 0 && errno != EINTR) {
      reason = std::strerror(errno);
      break;
    }
    if (fds[0].revents & POLLIN) clear_io_wake();
    if (fds[1].revents & (POLLIN | POLLHUP | POLLERR)) {
      const ssize_t n = ::recv(fd, buf, sizeof buf, MSG_DONTWAIT);
      if (n == 0) reason = "the server closed the connection";
      if (n < 0 && errno != EAGAIN && errno != EINTR) reason = std::strerror(errno);
      std::string_view rest(buf, n > 0 ? static_cast<std::size_t>(n) : 0);
      while (!rest.empty() && reason.empty()) {
        rest.remove_prefix(in.feed(rest));
        drain();
      }
    }
    if (!out.empty() && reason.empty()) {
      const ssize_t n = ::send(fd, out.data(), out.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n > 0) out.erase(0, static_cast<std::size_t>(n));
      if (n < 0 && errno != EAGAIN && errno != EINTR) reason = std::strerror(errno);
    }
  }
  if (!reason.empty()) log(LogLevel::Warn, "{}: connection lost: {}; reconnecting", where_, reason);
}

void SocketcandClient::discard_outgoing() {
  WireEvent e;
  while (pop_for_wire(e)) wire_dropped_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace sim
