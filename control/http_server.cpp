#include "control/http_server.h"

#include <arpa/inet.h>
#include <microhttpd.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <strings.h>
#include <sys/epoll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <thread>
#include <unordered_map>

#include "control/http_head.h"
#include "control/server_thread_priority.h"

namespace control::http {

namespace {

bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && ::strncasecmp(a.data(), b.data(), a.size()) == 0;
}

const std::string* find(const std::vector<std::pair<std::string, std::string>>& list, std::string_view name,
                        bool case_insensitive) {
  for (const auto& [k, v] : list)
    if (case_insensitive ? same_name(k, name) : k == name) return &v;
  return nullptr;
}

}  // namespace

const std::string* Request::header(std::string_view name) const { return find(headers, name, true); }
bool Request::has_param(std::string_view name) const { return find(query, name, false) != nullptr; }
std::string Request::param(std::string_view name) const {
  const auto* v = find(query, name, false);
  return v ? *v : std::string();
}

std::string error_body(const std::string& reason) {
  return nlohmann::json{{"error", reason}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

namespace {

Response error(int status, const std::string& reason) {
  Response r;
  r.status = status;
  r.body = error_body(reason);
  return r;
}

}  // namespace

struct Router::Route {
  std::string method;
  std::regex pattern;
  Handler handler;
};

void Router::add(std::string method, const std::string& pattern, Handler handler) {
  routes_.push_back(std::make_shared<const Route>(Route{std::move(method), std::regex(pattern), std::move(handler)}));
}

bool Router::dispatch(Request& request, Response& response) const {
  std::string allowed;
  std::smatch m;
  for (const auto& route : routes_) {
    if (!std::regex_match(request.path, m, route->pattern)) continue;
    if (route->method != request.method) {
      if (allowed.find(route->method) == std::string::npos) allowed += (allowed.empty() ? "" : ", ") + route->method;
      continue;
    }
    request.matches.assign(m.begin(), m.end());
    route->handler(request, response);
    return true;
  }
  if (allowed.empty()) return false;
  response = error(405, request.method + " is not allowed on " + request.path + " (use " + allowed + ")");
  response.headers.emplace_back("Allow", allowed);
  return true;
}

/// A connection libmicrohttpd holds, from the gate's accept (its socket context): the deadline
/// sweep closes it when its request is not complete in time.
struct Tracked {
  int fd = -1;
  std::chrono::steady_clock::time_point accepted;
  bool done = false;  ///< the request is complete (or answered): the deadline no longer applies
};

/// One request on its way through the server: filled on the connection thread, answered by a
/// worker, sent by the connection thread.
struct Exchange {
  enum class Phase { Reading, Refused, Queued, Answered, Streaming } phase = Phase::Reading;
  std::mutex* server_mu = nullptr;  ///< the server's lock (streams: against the ticker)
  MHD_Connection* connection = nullptr;
  Tracked* tracked = nullptr;
  Request request;
  Response response;
  std::size_t discarded = 0;  ///< body bytes past the limit (a refused chunked body)
  // Streaming: the stream's state, shared between the connection thread and the ticker.
  std::string pending;
  std::size_t pending_at = 0;
  std::chrono::steady_clock::time_point last_write;
  bool suspended = false;
  bool finished = false;
};

struct Server::Impl {
  Limits limits;
  Handler handler;
  Admission admission;
  int listen_fd = -1;
  MHD_Daemon* daemon = nullptr;

  std::mutex mu;  // the work queue, the suspended streams, the tracked connections, stopping
  std::condition_variable work_cv, tick_cv;
  std::deque<Exchange*> queue;
  std::set<Exchange*> streams;
  std::set<Tracked*> tracked;
  std::unordered_map<int, std::chrono::steady_clock::time_point> handed;  ///< fd → accept time, until MHD starts it
  bool stopping = false;
  std::vector<std::thread> workers;
  std::thread ticker;

  // ---- the gate: accepts, waits for a whole head that libmicrohttpd will parse, hands it over --
  // libmicrohttpd answers what it cannot parse with built-in HTML and has no hook to change that;
  // the gate refuses all of it first, with JSON (control/http_head.h). It only peeks, so the
  // connection reaches libmicrohttpd with every byte; each connection carries one request
  // (answers say Connection: close), so every request passes the gate.
  struct Pending {
    sockaddr_storage address{};
    socklen_t address_size = 0;
    std::chrono::steady_clock::time_point accepted, last_input;
    bool draining = false;  ///< refused: reading what still comes, so the answer is not lost to a reset
    std::chrono::steady_clock::time_point drain_until;
  };
  int epoll_fd = -1;
  std::atomic<bool> gate_stopping{false};
  std::thread gate;
  std::unordered_map<int, Pending> pending;  // the gate's thread only

  HeadLimits head_limits() const { return HeadLimits{limits.max_head, limits.max_headers}; }

  void gate_loop() {
    lower_this_thread_priority();
    std::string peeked(limits.max_head, '\0');
    epoll_event events[64];
    while (!gate_stopping) {
      const int n = ::epoll_wait(epoll_fd, events, 64, 50);
      for (int i = 0; i < n; ++i) {
        if (events[i].data.fd == listen_fd)
          accept_all();
        else
          on_readable(events[i].data.fd, peeked);
      }
      sweep_pending();
    }
    for (const auto& entry : pending) ::close(entry.first);
    pending.clear();
  }

  void accept_all() {
    for (;;) {
      Pending p;
      p.address_size = sizeof p.address;
      const int fd = ::accept4(listen_fd, reinterpret_cast<sockaddr*>(&p.address), &p.address_size,
                               SOCK_NONBLOCK | SOCK_CLOEXEC);
      if (fd < 0) return;
      if (!room_for(p.address)) {
        ::close(fd);  // at the connection limit: refused at accept
        continue;
      }
      p.accepted = p.last_input = std::chrono::steady_clock::now();
      epoll_event ev{};
      ev.events = EPOLLIN | EPOLLET | EPOLLRDHUP;  // edge-triggered: peeked bytes stay readable
      ev.data.fd = fd;
      if (::epoll_ctl(epoll_fd, EPOLL_CTL_ADD, fd, &ev) != 0) {
        ::close(fd);
        continue;
      }
      pending.emplace(fd, p);
    }
  }

  /// The connection limits count the gate's connections and libmicrohttpd's together.
  bool room_for(const sockaddr_storage& address) const {
    const auto* info = MHD_get_daemon_info(daemon, MHD_DAEMON_INFO_CURRENT_CONNECTIONS);
    if (pending.size() + (info ? info->num_connections : 0) >= limits.max_connections) return false;
    if (limits.max_connections_per_ip == 0 || address.ss_family != AF_INET) return true;
    const auto ip = reinterpret_cast<const sockaddr_in&>(address).sin_addr.s_addr;
    std::size_t same = 0;
    for (const auto& [fd, p] : pending)
      if (p.address.ss_family == AF_INET && reinterpret_cast<const sockaddr_in&>(p.address).sin_addr.s_addr == ip) ++same;
    return same < limits.max_connections_per_ip;
  }

  void on_readable(int fd, std::string& peeked) {
    const auto it = pending.find(fd);
    if (it == pending.end()) return;
    if (it->second.draining) {
      if (!discard_input(fd)) close_pending(it);
      return;
    }
    const auto n = ::recv(fd, peeked.data(), peeked.size(), MSG_PEEK);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
      close_pending(it);
      return;
    }
    if (n < 0) return;
    it->second.last_input = std::chrono::steady_clock::now();
    const auto verdict = check_head(std::string_view(peeked.data(), static_cast<std::size_t>(n)), head_limits());
    if (verdict.kind == HeadVerdict::Kind::Refused)
      refuse(it, verdict.status, verdict.reason);
    else if (verdict.kind == HeadVerdict::Kind::Complete)
      hand_over(it);
  }

  void hand_over(std::unordered_map<int, Pending>::iterator it) {
    const int fd = it->first;
    const Pending p = it->second;
    pending.erase(it);
    ::epoll_ctl(epoll_fd, EPOLL_CTL_DEL, fd, nullptr);
    {
      std::lock_guard lk(mu);
      handed[fd] = p.accepted;
    }
    // On failure (its own limits) libmicrohttpd has closed the socket.
    if (MHD_add_connection(daemon, fd, reinterpret_cast<const sockaddr*>(&p.address), p.address_size) != MHD_YES) {
      std::lock_guard lk(mu);
      handed.erase(fd);
    }
  }

  /// Answers with a JSON error, then reads (and drops) what the client still sends for a while.
  void refuse(std::unordered_map<int, Pending>::iterator it, int status, const std::string& reason) {
    const int fd = it->first;
    discard_input(fd);
    send_error(fd, status, reason);
    ::shutdown(fd, SHUT_WR);
    it->second.draining = true;
    it->second.drain_until = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  }

  /// Reads what is there; false once the client has closed.
  static bool discard_input(int fd) {
    char buf[16384];
    for (int i = 0; i < 64; ++i) {
      const auto n = ::recv(fd, buf, sizeof buf, MSG_DONTWAIT);
      if (n == 0) return false;
      if (n < 0) return errno == EAGAIN || errno == EINTR;
    }
    return true;
  }

  static void send_error(int fd, int status, const std::string& reason) {
    const auto body = error_body(reason);
    const char* phrase = MHD_get_reason_phrase_for(static_cast<unsigned>(status));
    const auto text = "HTTP/1.1 " + std::to_string(status) + " " + phrase +
                      "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
                      "\r\nConnection: close\r\n\r\n" + body;
    [[maybe_unused]] const auto sent = ::send(fd, text.data(), text.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  }

  void close_pending(std::unordered_map<int, Pending>::iterator it) {
    ::close(it->first);  // closing removes it from the epoll set
    pending.erase(it);
  }

  void sweep_pending() {
    const auto now = std::chrono::steady_clock::now();
    for (auto it = pending.begin(); it != pending.end();) {
      auto next = std::next(it);
      if (it->second.draining) {
        if (now >= it->second.drain_until) close_pending(it);
      } else if (now - it->second.accepted >= limits.request_deadline) {
        refuse(it, 408, deadline_reason());
      } else if (now - it->second.last_input >= std::chrono::seconds(limits.idle_timeout_s)) {
        close_pending(it);  // silent: closed, as libmicrohttpd closes an idle connection
      }
      it = next;
    }
  }

  std::string deadline_reason() const {
    return "the request was not complete within " + std::to_string(limits.request_deadline.count()) +
           " ms of connecting";
  }

  // ---- connections libmicrohttpd holds: the whole-request deadline --------------------------
  static void on_connection(void* cls, MHD_Connection* c, void** socket_context, MHD_ConnectionNotificationCode code) {
    auto* self = static_cast<Impl*>(cls);
    std::lock_guard lk(self->mu);
    if (code == MHD_CONNECTION_NOTIFY_STARTED) {
      const auto* info = MHD_get_connection_info(c, MHD_CONNECTION_INFO_CONNECTION_FD);
      auto* t = new Tracked;
      t->fd = info ? info->connect_fd : -1;
      const auto h = self->handed.find(t->fd);
      t->accepted = h != self->handed.end() ? h->second : std::chrono::steady_clock::now();
      if (h != self->handed.end()) self->handed.erase(h);
      *socket_context = t;
      self->tracked.insert(t);
    } else if (auto* t = static_cast<Tracked*>(*socket_context)) {
      // Before libmicrohttpd closes the socket: the sweep never touches a closed (reused) fd.
      self->tracked.erase(t);
      delete t;
      *socket_context = nullptr;
    }
  }

  /// The request is complete or answered (under mu).
  static void request_done(Exchange* ex) {
    if (ex->tracked) ex->tracked->done = true;
  }

  /// Connections whose request is still incomplete past the deadline (a client trickling bytes
  /// keeps resetting the idle timeout): a 408, then the socket is shut down and libmicrohttpd
  /// closes it. Only while it still reads the request, so nothing of its own is being written.
  void sweep_tracked() {
    const auto now = std::chrono::steady_clock::now();
    for (auto* t : tracked)
      if (!t->done && now - t->accepted >= limits.request_deadline) {
        t->done = true;
        send_error(t->fd, 408, deadline_reason());
        ::shutdown(t->fd, SHUT_RDWR);
      }
  }

  // ---- the connection thread ------------------------------------------------------------------
  static MHD_Result on_request(void* cls, MHD_Connection* c, const char* url, const char* method, const char*,
                               const char* upload, size_t* upload_size, void** con_cls) {
    return static_cast<Impl*>(cls)->request(c, url, method, upload, upload_size, con_cls);
  }

  MHD_Result request(MHD_Connection* c, const char* url, const char* method, const char* upload, size_t* upload_size,
                     void** con_cls) {
    lower_this_thread_priority();  // the connection thread (once): below the scheduler
    auto* ex = static_cast<Exchange*>(*con_cls);
    if (!ex) {
      ex = new Exchange;
      *con_cls = ex;
      ex->server_mu = &mu;
      ex->connection = c;
      if (const auto* info = MHD_get_connection_info(c, MHD_CONNECTION_INFO_SOCKET_CONTEXT))
        ex->tracked = static_cast<Tracked*>(info->socket_context);
      ex->request.method = method;
      ex->request.path = url;
      MHD_get_connection_values_n(c, MHD_HEADER_KIND, &Impl::collect, &ex->request.headers);
      MHD_get_connection_values_n(c, MHD_GET_ARGUMENT_KIND, &Impl::collect, &ex->request.query);
      if (auto refusal = screen(ex->request); refusal.status != 0) {
        ex->phase = Exchange::Phase::Refused;
        ex->response = std::move(refusal);
        {
          std::lock_guard lk(mu);
          request_done(ex);
        }
        return send(ex);  // before any body byte is read
      }
      return MHD_YES;
    }
    if (*upload_size > 0) {
      // Every framing ends here (Content-Length, chunked): the limit holds for all of them.
      if (ex->phase == Exchange::Phase::Reading && ex->request.body.size() + *upload_size > limits.max_body) {
        ex->phase = Exchange::Phase::Refused;
        ex->response = error(413, "the body is larger than " + std::to_string(limits.max_body) + " bytes");
        ex->request.body = std::string();
      }
      if (ex->phase == Exchange::Phase::Refused) {
        // The answer can only go once the body has ended: read on (bounded), then close.
        ex->discarded += *upload_size;
        if (ex->discarded > 16 * limits.max_body) return MHD_NO;
      } else {
        ex->request.body.append(upload, *upload_size);
      }
      *upload_size = 0;
      return MHD_YES;
    }
    switch (ex->phase) {
      case Exchange::Phase::Reading: {
        std::lock_guard lk(mu);
        request_done(ex);
        if (stopping) {
          ex->response = error(503, "the server is stopping");
        } else if (queue.size() >= limits.max_queued) {
          ex->response = error(503, "the server is busy (" + std::to_string(limits.max_queued) +
                                        " requests already wait): retry later");
        } else {
          ex->phase = Exchange::Phase::Queued;
          MHD_suspend_connection(c);
          queue.push_back(ex);
          work_cv.notify_one();
          return MHD_YES;
        }
        ex->phase = Exchange::Phase::Refused;
        return send(ex);
      }
      case Exchange::Phase::Refused:
      case Exchange::Phase::Answered: return send(ex);
      case Exchange::Phase::Queued:
      case Exchange::Phase::Streaming: return MHD_YES;
    }
    return MHD_YES;
  }

  /// What is checked once the headers are in (the gate has checked their syntax and count).
  Response screen(const Request& r) const {
    if (const auto* enc = r.header("Content-Encoding"); enc && !same_name(*enc, "identity"))
      return error(415, "compressed bodies are not accepted (Content-Encoding: " + *enc + ")");
    if (const auto* len = r.header("Content-Length")) {
      char* end = nullptr;
      const auto n = std::strtoull(len->c_str(), &end, 10);
      if (!len->empty() && *end == '\0' && n > limits.max_body)
        return error(413, "the body is larger than " + std::to_string(limits.max_body) + " bytes");
    }
    Response r2 = admission ? admission(r) : Response{0, {}, {}, {}, {}};
    return r2;
  }

  static MHD_Result collect(void* cls, MHD_ValueKind, const char* key, size_t key_size, const char* value,
                            size_t value_size) {
    auto* list = static_cast<std::vector<std::pair<std::string, std::string>>*>(cls);
    list->emplace_back(std::string(key, key_size), value ? std::string(value, value_size) : std::string());
    return MHD_YES;
  }

  MHD_Result send(Exchange* ex) {
    auto& res = ex->response;
    MHD_Response* r = nullptr;
    if (res.stream) {
      ex->phase = Exchange::Phase::Streaming;
      ex->last_write = std::chrono::steady_clock::now();
      r = MHD_create_response_from_callback(MHD_SIZE_UNKNOWN, 16 * 1024, &Impl::stream_body, ex, nullptr);
      std::lock_guard lk(mu);
      streams.insert(ex);
    } else {
      r = MHD_create_response_from_buffer(res.body.size(), res.body.data(), MHD_RESPMEM_MUST_COPY);
    }
    if (!r) return MHD_NO;
    MHD_add_response_header(r, "Content-Type", res.type.c_str());
    MHD_add_response_header(r, "Connection", "close");  // one request per connection: each passes the gate
    for (const auto& [k, v] : res.headers) MHD_add_response_header(r, k.c_str(), v.c_str());
    const auto ok = MHD_queue_response(ex->connection, static_cast<unsigned>(res.status), r);
    MHD_destroy_response(r);
    return ok;
  }

  /// The stream's body: what the stream has; nothing ready: suspend until the ticker's next round.
  static ssize_t stream_body(void* cls, uint64_t, char* buf, size_t max) {
    auto* ex = static_cast<Exchange*>(cls);
    if (ex->pending_at >= ex->pending.size()) {
      ex->pending.clear();
      ex->pending_at = 0;
      std::lock_guard lk(*ex->server_mu);
      const bool open = !ex->finished && ex->response.stream->poll(ex->pending);
      const auto now = std::chrono::steady_clock::now();
      if (ex->pending.empty() && open && now - ex->last_write >= std::chrono::seconds(1))
        ex->pending = ": keep-alive\n\n";  // a proxy or a browser sees the stream is alive
      if (ex->pending.empty()) {
        if (!open) return MHD_CONTENT_READER_END_OF_STREAM;
        ex->suspended = true;
        MHD_suspend_connection(ex->connection);
        return 0;
      }
      ex->last_write = now;
    }
    const auto n = std::min(max, ex->pending.size() - ex->pending_at);
    std::copy_n(ex->pending.data() + ex->pending_at, n, buf);
    ex->pending_at += n;
    return static_cast<ssize_t>(n);
  }

  static void on_completed(void* cls, MHD_Connection*, void** con_cls, MHD_RequestTerminationCode) {
    auto* self = static_cast<Impl*>(cls);
    auto* ex = static_cast<Exchange*>(*con_cls);
    if (!ex) return;
    *con_cls = nullptr;
    {
      std::lock_guard lk(self->mu);
      self->streams.erase(ex);
    }
    if (ex->response.stream) ex->response.stream->close();
    delete ex;
  }

  // ---- workers and the ticker -----------------------------------------------------------------
  void work() {
    lower_this_thread_priority();
    std::unique_lock lk(mu);
    for (;;) {
      work_cv.wait(lk, [this] { return stopping || !queue.empty(); });
      if (queue.empty()) return;
      auto* ex = queue.front();
      queue.pop_front();
      lk.unlock();
      try {
        handler(ex->request, ex->response);
      } catch (const std::exception& e) {
        ex->response = error(500, std::string("internal error: ") + e.what());
      }
      lk.lock();
      ex->phase = Exchange::Phase::Answered;
      MHD_resume_connection(ex->connection);  // the connection thread calls request() again: send
    }
  }

  /// Every 50 ms: the suspended streams poll again (events are batched at 20 Hz anyway).
  void tick() {
    lower_this_thread_priority();
    std::unique_lock lk(mu);
    while (!stopping) {
      tick_cv.wait_for(lk, std::chrono::milliseconds(50), [this] { return stopping; });
      sweep_tracked();
      for (auto* ex : streams)
        if (ex->suspended) {
          ex->suspended = false;
          MHD_resume_connection(ex->connection);
        }
    }
  }
};

Server::Server(Limits limits, Handler handler, Admission admission) : impl_(std::make_unique<Impl>()) {
  impl_->limits = limits;
  impl_->handler = std::move(handler);
  impl_->admission = std::move(admission);
}

Server::~Server() {
  stop();
  if (impl_->listen_fd >= 0) ::close(impl_->listen_fd);
}

std::string Server::listen(const std::string& address, int port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1) return "'" + address + "' is not an IPv4 address";
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return "cannot open a socket";
  const int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 128) != 0) {
    ::close(fd);
    return "cannot listen on " + address + ":" + std::to_string(port) + " (in use?)";
  }
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  port_ = ntohs(a.sin_port);
  impl_->listen_fd = fd;
  return {};
}

void Server::start() {
  auto& s = *impl_;
  if (s.daemon || s.listen_fd < 0) return;
  s.stopping = false;
  // The gate accepts (MHD_USE_NO_LISTEN_SOCKET); suspend/resume brings the inter-thread channel
  // MHD_add_connection needs.
  s.daemon = MHD_start_daemon(
      MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_EPOLL | MHD_ALLOW_SUSPEND_RESUME | MHD_USE_NO_LISTEN_SOCKET, 0, nullptr,
      nullptr, &Impl::on_request, &s, MHD_OPTION_CONNECTION_LIMIT, s.limits.max_connections,
      MHD_OPTION_PER_IP_CONNECTION_LIMIT, s.limits.max_connections_per_ip, MHD_OPTION_CONNECTION_TIMEOUT,
      s.limits.idle_timeout_s, MHD_OPTION_CONNECTION_MEMORY_LIMIT, s.limits.connection_memory,
      MHD_OPTION_NOTIFY_COMPLETED, &Impl::on_completed, &s, MHD_OPTION_NOTIFY_CONNECTION, &Impl::on_connection, &s,
      MHD_OPTION_END);
  if (!s.daemon) return;
  s.epoll_fd = ::epoll_create1(EPOLL_CLOEXEC);
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.fd = s.listen_fd;
  ::epoll_ctl(s.epoll_fd, EPOLL_CTL_ADD, s.listen_fd, &ev);
  s.gate_stopping = false;
  s.gate = std::thread([&s] { s.gate_loop(); });
  for (std::size_t i = 0; i < s.limits.workers; ++i) s.workers.emplace_back([&s] { s.work(); });
  s.ticker = std::thread([&s] { s.tick(); });
}

void Server::stop() {
  auto& s = *impl_;
  if (!s.daemon) return;
  s.gate_stopping = true;  // no new connections reach the daemon
  if (s.gate.joinable()) s.gate.join();
  ::close(s.epoll_fd);
  s.epoll_fd = -1;
  {
    std::lock_guard lk(s.mu);
    s.stopping = true;
    // Streams end; every suspended connection resumes so the daemon can close it.
    for (auto* ex : s.streams) {
      ex->finished = true;
      if (ex->suspended) {
        ex->suspended = false;
        MHD_resume_connection(ex->connection);
      }
    }
  }
  s.work_cv.notify_all();
  s.tick_cv.notify_all();
  for (auto& w : s.workers) w.join();
  s.workers.clear();
  if (s.ticker.joinable()) s.ticker.join();
  {
    std::lock_guard lk(s.mu);
    for (auto* ex : s.queue) {  // never reached a worker
      ex->response = error(503, "the server is stopping");
      ex->phase = Exchange::Phase::Answered;
      MHD_resume_connection(ex->connection);
    }
    s.queue.clear();
  }
  MHD_stop_daemon(s.daemon);
  s.daemon = nullptr;
}

}  // namespace control::http
