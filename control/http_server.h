// The control plane's HTTP server: libmicrohttpd (Debian's libmicrohttpd-dev) behind a small
// interface of our own, so the routes never see the library. Why this library and how it is
// bounded: docs/architecture.md (the control plane) and docs/api.md (limits).
//
// Threads: a gate thread accepts and peeks at each connection until its head (request line and
// headers) is in, refuses what libmicrohttpd could not parse (control/http_head.h) and hands the
// rest over. One libmicrohttpd epoll thread then owns every connection (reading headers and
// bodies, writing answers), so a silent or slow client costs a socket and a bounded buffer, never
// a thread. A complete request is handed to a fixed pool of workers (handlers may wait on the
// simulation); its connection is suspended meanwhile. Requests wait in a bounded queue: beyond it,
// 503. A ticker thread polls the streams and closes connections past the whole-request deadline.
// One request per connection (Connection: close), so every request passes the gate.
//
// Every refusal is a JSON error: at the gate, a malformed request line or header (400), an HTTP
// version other than 1.0/1.1 (505), a request line past the head limit (414), a head past it or
// too many fields (431), Transfer-Encoding (411), the deadline (408); before a handler runs,
// Content-Encoding (415), a body over the limit (413), and the admission check the owner gives
// (Host/Origin, 403), which runs once the headers are in and before any body is read.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace control::http {

struct Request {
  std::string method;
  std::string path;  ///< decoded, without the query
  std::vector<std::pair<std::string, std::string>> headers;
  std::vector<std::pair<std::string, std::string>> query;
  std::string body;
  std::vector<std::string> matches;  ///< the route's capture groups ([0] = the whole path)

  const std::string* header(std::string_view name) const;  ///< case-insensitive
  std::string header_value(std::string_view name) const { const auto* h = header(name); return h ? *h : std::string(); }
  bool has_header(std::string_view name) const { return header(name) != nullptr; }
  bool has_param(std::string_view name) const;
  std::string param(std::string_view name) const;
};

/// A response body produced over time (server-sent events). poll() never blocks: it appends what
/// is ready to `out` and returns false once the stream is over. The server polls it when it may
/// have more (every 50 ms) and closes it once the client has gone.
class Stream {
 public:
  virtual ~Stream() = default;
  virtual bool poll(std::string& out) = 0;
  virtual void close() = 0;
};

struct Response {
  int status = 200;
  std::string type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;
  std::shared_ptr<Stream> stream;  ///< set: `body` is ignored, the stream is the body
};

/// Limits of one server (docs/api.md states them).
struct Limits {
  std::size_t max_body = 64 * 1024;  ///< request body (Content-Length; other framings are refused)
  std::size_t max_headers = 64;      ///< header fields per request (and query parameters, cookies)
  std::size_t max_head = 16 * 1024;  ///< request line + header block
  /// libmicrohttpd's memory per connection: room for the largest head the gate lets through, its
  /// parsed fields and the read buffer.
  std::size_t connection_memory = 64 * 1024;
  unsigned max_connections = 1024;      ///< the gate's and libmicrohttpd's together
  unsigned max_connections_per_ip = 0;  ///< 0 = no per-address limit
  unsigned idle_timeout_s = 10;         ///< a connection that sends nothing this long is closed
  /// From accept to the whole request (head and body) in: a client trickling bytes keeps the
  /// idle timeout from firing, not this one. Beyond: 408 and the connection is closed.
  std::chrono::milliseconds request_deadline{10000};
  std::size_t workers = 8;
  std::size_t max_queued = 64;  ///< complete requests waiting for a worker; beyond: 503
};

using Handler = std::function<void(Request&, Response&)>;
/// Runs once a request's headers are in, on the connection thread (it must not block): a
/// status != 0 answers the request at once, before its body is read.
using Admission = std::function<Response(const Request&)>;

/// Routes by method and path pattern (std::regex, whole path). Kept apart from the server so the
/// whole API can be mounted under a prefix, behind a check, by the owner.
class Router {
 public:
  void add(std::string method, const std::string& pattern, Handler handler);
  /// Calls the route for `request` (its matches filled). False when no pattern matches the path;
  /// a path known with other methods only is answered 405 naming them.
  bool dispatch(Request& request, Response& response) const;

 private:
  struct Route;
  std::vector<std::shared_ptr<const Route>> routes_;
};

class Server {
 public:
  Server(Limits limits, Handler handler, Admission admission);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// Listens on address:port (0 = an ephemeral port); returns an error message, empty on success.
  std::string listen(const std::string& address, int port);
  int port() const { return port_; }
  /// Starts answering (the connection thread and the workers).
  void start();
  /// Stops answering, closes every connection and joins the threads.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = 0;
};

/// A JSON error body {"error": reason}; always valid JSON, whatever bytes `reason` holds
/// (invalid UTF-8 is replaced).
std::string error_body(const std::string& reason);

}  // namespace control::http
