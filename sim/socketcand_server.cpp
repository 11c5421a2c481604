#include "sim/socketcand_server.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <vector>

#include <fmt/format.h>

#include "sim/log.h"
#include "sim/socketcand_protocol.h"

namespace sim {

namespace {

std::int64_t monotonic_ms() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
}

// Text that is safe inside `< error ... >`: no brackets, printable.
std::string error_text(const std::string& reason) {
  std::string s = reason;
  for (char& c : s)
    if (c == '<' || c == '>' || c < 0x20 || c > 0x7E) c = '?';
  return s;
}

}  // namespace

struct SocketcandServer::Client {
  enum class Mode { NoBus, Bcm, Raw };
  int fd = -1;
  std::string peer;
  Mode mode = Mode::NoBus;
  socketcand::Splitter in;
  std::string out;
  std::int64_t settle_until_ms = 0;  // frames are held until then (see kRawmodeSettleMs)
  std::uint64_t errors = 0;          // messages answered with `< error ... >`
  std::uint32_t id = 0;              // the tag of its frames on the bus (never 0)
  int in_flight = 0;                 // its frames handed to the bus, not yet delivered or refused
  std::int64_t connected_ms = 0;     // for the handshake limit
  std::int64_t last_input_ms = 0;    // for the BCM-mode idle limit
};

std::unique_ptr<SocketcandServer> SocketcandServer::open(const std::string& channel, const TcpEndpoint& endpoint,
                                                         std::string& error, Limits limits) {
  const auto addr = resolve_tcp(endpoint, error);
  if (!addr) return nullptr;
  const int fd = ::socket(addr->family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) {
    error = std::string("socketcand server: socket: ") + std::strerror(errno);
    return nullptr;
  }
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&addr->addr), addr->len) != 0 || ::listen(fd, kMaxClients) != 0) {
    error = "socketcand server: cannot listen on " + endpoint.host + ":" + std::to_string(endpoint.port) + ": " +
            std::strerror(errno);
    ::close(fd);
    return nullptr;
  }
  sockaddr_storage bound{};
  socklen_t len = sizeof bound;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &len);
  const std::string where = to_string(reinterpret_cast<const sockaddr*>(&bound), len);
  std::uint16_t port = endpoint.port;
  if (bound.ss_family == AF_INET) port = ntohs(reinterpret_cast<const sockaddr_in*>(&bound)->sin_port);
  if (bound.ss_family == AF_INET6) port = ntohs(reinterpret_cast<const sockaddr_in6*>(&bound)->sin6_port);
  std::unique_ptr<SocketcandServer> server(new SocketcandServer(channel, channel, fd, port, limits));
  server->address_ = where;
  if (!server->eventfds_ok()) {
    error = std::string("socketcand server: eventfd: ") + std::strerror(errno);
    return nullptr;
  }
  if (!is_loopback(*addr))
    log(LogLevel::Warn, "socketcand: bus '{}' is served on {}, which is not a loopback address: anyone who can reach it "
        "can send frames to the plant", channel, where);
  log(LogLevel::Info, "socketcand: bus '{}' served on {} (channel '{}')", channel, where, channel);
  server->thread_ = std::thread([s = server.get()] { s->run(); });
  return server;
}

SocketcandServer::SocketcandServer(std::string name, std::string channel, int listen_fd, std::uint16_t port,
                                   Limits limits)
    : QueuedTransport(std::move(name)), channel_(std::move(channel)), limits_(limits), listen_fd_(listen_fd), port_(port) {}

SocketcandServer::~SocketcandServer() {
  request_stop();
  if (thread_.joinable()) thread_.join();
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

void SocketcandServer::run() {
  auto& clients = clients_;
  std::vector<pollfd> fds;
  while (!stop_requested()) {
    const std::int64_t now = monotonic_ms();
    int timeout = expire_clients(now);
    fds.clear();
    fds.push_back(pollfd{io_wake_fd(), POLLIN, 0});
    fds.push_back(pollfd{listen_fd_, POLLIN, 0});
    for (const auto& c : clients) {
      short events = POLLIN;
      if (!c->out.empty()) {
        if (now >= c->settle_until_ms)
          events |= POLLOUT;
        else
          timeout = static_cast<int>(std::min<std::int64_t>(timeout < 0 ? 1000 : timeout, c->settle_until_ms - now + 1));
      }
      fds.push_back(pollfd{c->fd, events, 0});
    }
    if (::poll(fds.data(), fds.size(), timeout) < 0 && errno != EINTR) {
      log(LogLevel::Error, "socketcand: poll failed: {}", std::strerror(errno));
      break;
    }
    if (fds[0].revents & POLLIN) {
      clear_io_wake();
      WireEvent e;
      while (pop_for_wire(e)) on_wire_event(e);
    }
    const std::size_t polled = fds.size() - 2;
    for (std::size_t i = 0; i < polled; ++i) {
      if (clients[i]->fd >= 0 && (fds[2 + i].revents & (POLLIN | POLLHUP | POLLERR))) read_client(*clients[i]);
    }
    if (fds[1].revents & POLLIN) accept_clients();
    for (auto& c : clients) flush(*c);
    std::erase_if(clients, [](const auto& c) { return c->fd < 0; });
    clients_now_.store(static_cast<int>(clients.size()), std::memory_order_relaxed);
  }
  for (auto& c : clients)
    if (c->fd >= 0) ::close(c->fd);
  clients.clear();
}

int SocketcandServer::expire_clients(std::int64_t now_ms) {
  std::int64_t next = -1;
  const auto until = [&](std::int64_t deadline) {
    if (deadline > now_ms && (next < 0 || deadline - now_ms < next)) next = deadline - now_ms;
    return deadline <= now_ms;
  };
  for (auto& c : clients_) {
    if (c->fd < 0) continue;
    if (c->mode == Client::Mode::NoBus && until(c->connected_ms + limits_.handshake_ms))
      drop(*c, "no '< open " + channel_ + " >' within " + std::to_string(limits_.handshake_ms) + " ms of connecting");
    else if (c->mode == Client::Mode::Bcm && until(c->last_input_ms + limits_.bcm_idle_ms))
      drop(*c, "idle in BCM mode for " + std::to_string(limits_.bcm_idle_ms) + " ms");
  }
  std::erase_if(clients_, [](const auto& c) { return c->fd < 0; });
  clients_now_.store(static_cast<int>(clients_.size()), std::memory_order_relaxed);
  return static_cast<int>(std::min<std::int64_t>(next, 1000 * 1000));
}

void SocketcandServer::accept_clients() {
  for (;;) {
    sockaddr_storage peer{};
    socklen_t len = sizeof peer;
    const int fd = ::accept4(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &len, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;  // EAGAIN: no more; other errors (EMFILE, ...) are retried on the next poll
    const std::string who = to_string(reinterpret_cast<const sockaddr*>(&peer), len);
    if (static_cast<int>(clients_.size()) >= kMaxClients) {
      log(LogLevel::Warn, "socketcand: bus '{}': refusing {}: already {} clients", channel_, who, kMaxClients);
      static constexpr char kFull[] = "< error too many clients >";
      [[maybe_unused]] const auto n = ::send(fd, kFull, sizeof kFull - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
      ::close(fd);
      clients_dropped_.fetch_add(1, std::memory_order_relaxed);
      continue;
    }
    const int one = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    auto c = std::make_unique<Client>();
    c->fd = fd;
    c->peer = who;
    c->id = next_client_id_++;
    if (next_client_id_ == 0) next_client_id_ = 1;
    c->connected_ms = c->last_input_ms = monotonic_ms();
    c->out.reserve(64 * 1024);  // grows (on this thread) up to kMaxPendingOutput if needed
    log(LogLevel::Info, "socketcand: bus '{}': client {} connected", channel_, who);
    enqueue(*c, "< hi >");
    clients_.push_back(std::move(c));
  }
}

void SocketcandServer::read_client(Client& c) {
  char buf[4096];
  for (int round = 0; round < 8 && c.fd >= 0; ++round) {
    const ssize_t n = ::recv(c.fd, buf, sizeof buf, MSG_DONTWAIT);
    if (n == 0) {
      log(LogLevel::Info, "socketcand: bus '{}': client {} disconnected", channel_, c.peer);
      ::close(c.fd);
      c.fd = -1;
      return;
    }
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return;
      log(LogLevel::Info, "socketcand: bus '{}': client {} lost: {}", channel_, c.peer, std::strerror(errno));
      ::close(c.fd);
      c.fd = -1;
      return;
    }
    c.last_input_ms = monotonic_ms();
    std::string_view rest(buf, static_cast<std::size_t>(n));
    while (!rest.empty() && c.fd >= 0) {
      rest.remove_prefix(c.in.feed(rest));
      std::string_view message;
      std::string error;
      for (;;) {
        const auto r = c.in.next(message, error);
        if (r == socketcand::Splitter::Result::NeedMore) break;
        if (r == socketcand::Splitter::Result::Error) {
          drop(c, error);
          return;
        }
        handle(c, message);
        if (c.fd < 0) return;
      }
    }
  }
}

void SocketcandServer::handle(Client& c, std::string_view text) {
  socketcand::Message m;
  std::string error;
  // A complete message that does not parse is answered and skipped: the stream is still in step.
  if (!socketcand::parse(text, m, error)) return refuse(c, error);
  using Kind = socketcand::Kind;
  if (c.mode == Client::Mode::NoBus) {
    if (m.kind == Kind::Open) {
      if (m.text != channel_) return drop(c, "unknown bus '" + std::string(m.text) + "' (this server has '" + channel_ + "')");
      c.mode = Client::Mode::Bcm;
      return enqueue(c, "< ok >");
    }
    if (m.kind == Kind::Echo) return enqueue(c, "\n< echo >");
    return refuse(c, "expected '< open " + channel_ + " >' first");
  }
  switch (m.kind) {
    case Kind::Rawmode:
      c.mode = Client::Mode::Raw;
      enqueue(c, "< ok >");
      flush(c);
      c.settle_until_ms = monotonic_ms() + kRawmodeSettleMs;
      raw_client_seen_.store(true, std::memory_order_release);
      return;
    case Kind::Bcmmode:
      c.mode = Client::Mode::Bcm;
      return enqueue(c, "< ok >");
    case Kind::Echo:
      return enqueue(c, "\n< echo >");
    case Kind::Send:
      return forward_from(c, m.frame);
    default:
      return refuse(c, "unexpected '" + std::string(text.substr(0, 24)) + "' from a client");
  }
}

void SocketcandServer::refuse(Client& c, const std::string& reason) {
  ++c.errors;
  if (c.errors == 1 || c.errors % 1000 == 0)
    log(LogLevel::Warn, "socketcand: bus '{}': client {}: {} ({} refused message(s) so far)", channel_, c.peer, reason,
        c.errors);
  enqueue(c, "\n< error " + error_text(reason) + " >");
}

void SocketcandServer::forward_from(Client& from, const CanFrame& frame) {
  // The client's own transmit queue: a frame reaches the other clients only when the bus has
  // carried it (on_wire_event), so a client can have at most this many frames on the way.
  if (from.in_flight >= kClientTxQueue)
    return refuse(from, fmt::format("frame {:03X} refused: {} frames of this client wait for the bus", frame.id,
                                    from.in_flight));
  if (!push_to_bus(frame, from.id)) {
    const auto dropped = rx_dropped();
    if (dropped == 1 || dropped % 1000 == 0)
      log(LogLevel::Warn, "socketcand: bus '{}': the scheduler is behind; {} frame(s) from clients dropped", channel_,
          dropped);
    return refuse(from, fmt::format("frame {:03X} refused: the simulation is behind", frame.id));
  }
  ++from.in_flight;
  notify_bus();
}

void SocketcandServer::on_wire_event(const WireEvent& e) {
  using Kind = WireEvent::Kind;
  if (e.kind == Kind::Frame) return broadcast(e.frame, nullptr);
  Client* from = nullptr;
  for (auto& c : clients_)
    if (c->id == e.tag && c->fd >= 0) from = c.get();
  if (from) --from->in_flight;
  if (e.kind == Kind::Delivered) return broadcast(e.frame, from);
  if (e.kind == Kind::Refused && from)
    refuse(*from, fmt::format("frame {:03X} refused: the bus's transmit queue is full", e.frame.id));
}

void SocketcandServer::broadcast(const CanFrame& frame, const Client* except) {
  timespec ts{};
  ::clock_gettime(CLOCK_REALTIME, &ts);
  // A newline before each frame: python-can 4.1 drops the byte after the last message it parsed
  // from one recv(), which would otherwise be the '<' of a message cut in two.
  char text[socketcand::kFormatMax + 1];
  text[0] = '\n';
  const std::size_t n = socketcand::format_frame(frame, ts.tv_sec, ts.tv_nsec / 1000, text + 1);
  for (auto& c : clients_) {
    if (c.get() == except || c->fd < 0 || c->mode != Client::Mode::Raw) continue;
    enqueue(*c, std::string_view(text, n + 1));
  }
}

void SocketcandServer::enqueue(Client& c, std::string_view text) {
  if (c.fd < 0) return;
  if (c.out.size() + text.size() > kMaxPendingOutput)
    return drop(c, "the client does not read (" + std::to_string(c.out.size()) + " bytes pending)");
  c.out.append(text);
}

void SocketcandServer::flush(Client& c) {
  if (c.fd < 0 || c.out.empty() || monotonic_ms() < c.settle_until_ms) return;
  const ssize_t n = ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  if (n > 0) {
    c.out.erase(0, static_cast<std::size_t>(n));
  } else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
    log(LogLevel::Info, "socketcand: bus '{}': client {} lost: {}", channel_, c.peer, std::strerror(errno));
    ::close(c.fd);
    c.fd = -1;
  }
}

void SocketcandServer::drop(Client& c, const std::string& reason) {
  if (c.fd < 0) return;
  log(LogLevel::Warn, "socketcand: bus '{}': closing client {}: {}", channel_, c.peer, reason);
  const std::string text = "\n< error " + error_text(reason) + " >";
  [[maybe_unused]] const auto n = ::send(c.fd, text.data(), text.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  ::close(c.fd);
  c.fd = -1;
  clients_dropped_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace sim
