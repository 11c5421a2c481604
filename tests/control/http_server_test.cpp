// The control plane's HTTP server (control/http_server) under malformed and abusive requests
// (issue 25, items 1-6 and the queue bound), with small limits and a handler that counts what
// reaches it: a refused request never reaches a handler, and the answer is always JSON.
#include "control/http_server.h"

#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "tests/control/raw_http.h"

namespace {

using vtest::RawConnection;

bool is_json(const std::string& body) { return !nlohmann::json::parse(body, nullptr, false).is_discarded(); }

class HttpServer : public ::testing::Test {
 protected:
  void start(control::http::Limits limits = small_limits()) {
    server_ = std::make_unique<control::http::Server>(
        limits,
        [this](control::http::Request& req, control::http::Response& res) {
          ++handled_;
          {
            std::unique_lock lk(mu_);
            cv_.wait(lk, [this] { return !hold_; });
          }
          if (req.path == "/throw") throw std::runtime_error("bad \xff bytes");
          res.body = nlohmann::json{{"bytes", req.body.size()}}.dump();
        },
        [](const control::http::Request& req) {
          control::http::Response r;
          r.status = 0;
          if (req.header_value("Host") == "evil") {
            r.status = 403;
            r.body = control::http::error_body("Host '" + req.header_value("Host") + "' refused");
          }
          return r;
        });
    ASSERT_EQ(server_->listen("127.0.0.1", 0), "");
    server_->start();
  }
  static control::http::Limits small_limits() {
    control::http::Limits l;
    l.max_body = 1024;
    l.max_headers = 16;
    l.max_head = 4 * 1024;
    l.connection_memory = 16 * 1024;
    l.idle_timeout_s = 1;
    l.workers = 2;
    l.max_queued = 4;
    return l;
  }
  std::string exchange(const std::string& bytes) {
    RawConnection c(server_->port());
    EXPECT_TRUE(c.ok());
    c.send(bytes);
    return c.receive();
  }
  void release() {
    {
      std::lock_guard lk(mu_);
      hold_ = false;
    }
    cv_.notify_all();
  }
  void TearDown() override {
    release();
    if (server_) server_->stop();
  }

  std::unique_ptr<control::http::Server> server_;
  std::atomic<int> handled_{0};
  std::mutex mu_;
  std::condition_variable cv_;
  bool hold_ = false;
};

std::string chunked_post(std::size_t bytes) {
  std::string r = "POST /x HTTP/1.1\r\nHost: ok\r\nTransfer-Encoding: chunked\r\n\r\n";
  for (std::size_t sent = 0; sent < bytes; sent += 256) r += "100\r\n" + std::string(256, 'a') + "\r\n";
  return r + "0\r\n\r\n";
}

/// The status and JSON reason of a refusal; "" when the body is not a JSON error.
std::string reason_of(const std::string& response) {
  const auto j = nlohmann::json::parse(RawConnection::body(response), nullptr, false);
  return j.is_object() && j.contains("error") && j["error"].is_string() ? j["error"].get<std::string>() : "";
}

TEST_F(HttpServer, ChunkedBodiesAre411BeforeTheBodyIsRead) {
  start();
  const auto r = exchange(chunked_post(768));
  EXPECT_EQ(RawConnection::status(r), 411) << r;
  EXPECT_NE(reason_of(r).find("Content-Length"), std::string::npos) << r;
  // A body far over the limit: refused at its head, whatever follows.
  const auto big = exchange(chunked_post(1 << 20));
  EXPECT_EQ(RawConnection::status(big), 411) << big.substr(0, 200);
  EXPECT_EQ(handled_, 0);
}

/// Everything libmicrohttpd would refuse with its own HTML page is refused first, with JSON.
TEST_F(HttpServer, MalformedFramingGetsAJsonErrorNotLibmicrohttpdsPage) {
  start();
  struct Case {
    const char* what;
    std::string request;
    int status;
  };
  const std::string host = "Host: ok\r\n";
  const std::vector<Case> cases = {
      {"noise", std::string("\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03\r\n\r\n", 15), 400},
      {"no version", "GET /x\r\n" + host + "\r\n", 400},
      {"two spaces", "GET  /x HTTP/1.1\r\n" + host + "\r\n", 400},
      {"not a path", "GET x HTTP/1.1\r\n" + host + "\r\n", 400},
      {"bad method", "G(T /x HTTP/1.1\r\n" + host + "\r\n", 400},
      {"HTTP/2.0", "GET /x HTTP/2.0\r\n" + host + "\r\n", 505},
      {"HTTP/0.9", "GET /x HTTP/0.9\r\n" + host + "\r\n", 505},
      {"bad version", "GET /x HTTQ/1.1\r\n" + host + "\r\n", 400},
      {"no Host", "GET /x HTTP/1.1\r\n\r\n", 400},
      {"two Hosts", "GET /x HTTP/1.1\r\n" + host + host + "\r\n", 400},
      {"no colon", "GET /x HTTP/1.1\r\n" + host + "Broken header\r\n\r\n", 400},
      {"space in name", "GET /x HTTP/1.1\r\n" + host + "Bad Name: v\r\n\r\n", 400},
      {"folded", "GET /x HTTP/1.1\r\n" + host + "X-A: 1\r\n  2\r\n\r\n", 400},
      {"NUL in a value", "GET /x HTTP/1.1\r\n" + host + std::string("X-A: a\0b\r\n\r\n", 11), 400},
      {"Content-Length not a number", "POST /x HTTP/1.1\r\n" + host + "Content-Length: 1x\r\n\r\n1", 400},
      {"Content-Length overflows", "POST /x HTTP/1.1\r\n" + host + "Content-Length: 99999999999999999999999\r\n\r\n", 400},
      {"negative Content-Length", "POST /x HTTP/1.1\r\n" + host + "Content-Length: -1\r\n\r\n", 400},
      {"two Content-Lengths", "POST /x HTTP/1.1\r\n" + host + "Content-Length: 1\r\nContent-Length: 2\r\n\r\nab", 400},
      {"bad chunk size", "POST /x HTTP/1.1\r\n" + host + "Transfer-Encoding: chunked\r\n\r\nzz\r\nab\r\n0\r\n\r\n", 411},
      {"chunk size overflow", "POST /x HTTP/1.1\r\n" + host + "Transfer-Encoding: chunked\r\n\r\nfffffffffffffffffffff\r\n", 411},
      {"URL too long", "GET /" + std::string(5000, 'a') + " HTTP/1.1\r\n" + host + "\r\n", 414},
      {"too many query parameters", "GET /x?" + std::string(100 * 4, '&').replace(0, 400, [] {
         std::string q;
         for (int i = 0; i < 100; ++i) q += "a=" + std::to_string(i % 10) + "&";
         return q;
       }()) + " HTTP/1.1\r\n" + host + "\r\n", 414},
      {"head too large", "GET /x HTTP/1.1\r\n" + host + "X-Big: " + std::string(5000, 'v') + "\r\n\r\n", 431},
      {"too many header fields", [&] {
         std::string r = "GET /x HTTP/1.1\r\n" + host;
         for (int i = 0; i < 20; ++i) r += "X-" + std::to_string(i) + ": v\r\n";
         return r + "\r\n";
       }(), 431},
      {"too many cookies", "GET /x HTTP/1.1\r\n" + host + "Cookie: " + [] {
         std::string c;
         for (int i = 0; i < 40; ++i) c += "c" + std::to_string(i) + "=1; ";
         return c;
       }() + "\r\n\r\n", 431},
  };
  for (const auto& c : cases) {
    const auto r = exchange(c.request);
    EXPECT_EQ(RawConnection::status(r), c.status) << c.what << ": " << r.substr(0, 300);
    EXPECT_NE(r.find("Content-Type: application/json"), std::string::npos) << c.what;
    EXPECT_FALSE(reason_of(r).empty()) << c.what << ": " << r.substr(0, 300);
  }
  EXPECT_EQ(handled_, 0);
}

/// The largest head the gate lets through is one libmicrohttpd parses (its connection memory holds
/// it): the request reaches the handler, with the production limits.
TEST_F(HttpServer, TheLargestAcceptedHeadReachesTheHandler) {
  control::http::Limits limits;
  limits.workers = 2;
  start(limits);
  std::string query;
  for (std::size_t i = 0; i < limits.max_headers; ++i) query += "p" + std::to_string(i) + "=" + std::to_string(i) + "&";
  std::string cookies;
  for (std::size_t i = 0; i + 1 < limits.max_headers; ++i) cookies += "c" + std::to_string(i) + "=1;";
  std::string head = "GET /x?" + query + " HTTP/1.1\r\nHost: ok\r\nCookie: " + cookies + "\r\n";
  for (std::size_t i = 3; i < limits.max_headers; ++i) head += "X-" + std::to_string(i) + ": v\r\n";
  const auto filler = limits.max_head - head.size() - std::string("X-Fill: \r\n\r\n").size() - 1;
  head += "X-Fill: " + std::string(filler, 'f') + "\r\n\r\n";
  ASSERT_LT(head.size(), limits.max_head);
  const auto r = exchange(head);
  EXPECT_EQ(RawConnection::status(r), 200) << r.substr(0, 300);
  EXPECT_EQ(handled_, 1);
}

/// A client trickling its head, then one trickling its body, one byte every 100 ms: each byte
/// resets the idle timeout, the whole-request deadline (1 s here) still ends it with a 408.
TEST_F(HttpServer, TricklingClientsMeetTheWholeRequestDeadline) {
  auto limits = small_limits();
  limits.idle_timeout_s = 10;
  limits.request_deadline = std::chrono::milliseconds(1000);
  start(limits);
  const std::string head = "POST /x HTTP/1.1\r\nHost: ok\r\nContent-Length: 100\r\n\r\n";
  for (const bool body_phase : {false, true}) {
    RawConnection c(server_->port());
    ASSERT_TRUE(c.ok());
    const auto t0 = std::chrono::steady_clock::now();
    std::string trickle = body_phase ? std::string(100, 'b') : head;
    if (body_phase) c.send(head);
    std::string r;
    for (char byte : trickle) {
      if (!c.send(std::string(1, byte))) break;
      r = c.receive(std::chrono::milliseconds(100));
      if (!r.empty()) break;
    }
    if (r.empty()) r = c.receive();
    const auto waited = std::chrono::steady_clock::now() - t0;
    EXPECT_EQ(RawConnection::status(r), 408) << (body_phase ? "body: " : "head: ") << r;
    EXPECT_NE(reason_of(r).find("1000 ms"), std::string::npos) << r;
    EXPECT_GE(waited, std::chrono::milliseconds(1000));
    EXPECT_LT(waited, std::chrono::milliseconds(3000));
    EXPECT_TRUE(c.closed_by_peer(std::chrono::milliseconds(2000)));
  }
  EXPECT_EQ(handled_, 0);
}

TEST_F(HttpServer, EveryAnswerClosesItsConnection) {
  start();
  RawConnection c(server_->port());
  c.send("GET /x HTTP/1.1\r\nHost: ok\r\n\r\nGET /x HTTP/1.1\r\nHost: ok\r\n\r\n");  // pipelined
  const auto r = c.receive();
  EXPECT_EQ(RawConnection::status(r), 200) << r;
  EXPECT_NE(r.find("Connection: close"), std::string::npos) << r;
  EXPECT_TRUE(c.closed_by_peer(std::chrono::milliseconds(2000)));
  EXPECT_EQ(handled_, 1);  // the second request never reached a handler without passing the gate
}

TEST_F(HttpServer, ContentLengthOverTheLimitIs413BeforeTheBody) {
  start();
  const auto r = exchange("POST /x HTTP/1.1\r\nHost: ok\r\nContent-Length: 100000\r\n\r\n");
  EXPECT_EQ(RawConnection::status(r), 413) << r;
  EXPECT_TRUE(is_json(RawConnection::body(r)));
  EXPECT_EQ(handled_, 0);
}

TEST_F(HttpServer, CompressedBodyIs415) {
  start();
  const auto r = exchange("POST /x HTTP/1.1\r\nHost: ok\r\nContent-Encoding: gzip\r\nContent-Length: 4\r\n\r\nabcd");
  EXPECT_EQ(RawConnection::status(r), 415) << r;
  EXPECT_TRUE(is_json(RawConnection::body(r)));
  EXPECT_EQ(handled_, 0);
}

TEST_F(HttpServer, TooManyHeadersIs431) {
  start();
  std::string req = "GET /x HTTP/1.1\r\nHost: ok\r\n";
  for (int i = 0; i < 40; ++i) req += "X-H" + std::to_string(i) + ": v\r\n";
  const auto r = exchange(req + "\r\n");
  EXPECT_EQ(RawConnection::status(r), 431) << r;
  EXPECT_TRUE(is_json(RawConnection::body(r)));
  EXPECT_EQ(handled_, 0);
}

TEST_F(HttpServer, EndlessHeaderIsCutOffAtTheMemoryBound) {
  start();
  RawConnection c(server_->port());
  c.send("GET /x HTTP/1.1\r\nHost: ok\r\nX-Long: ");
  bool refused = false;
  for (int i = 0; i < 64 && !refused; ++i) refused = !c.send(std::string(1024, 'a'));
  const auto r = c.receive();
  // Answered 431 with a JSON reason once the header block passes the head limit.
  EXPECT_TRUE(refused || RawConnection::status(r) == 431) << r.substr(0, 200);
  if (!r.empty()) {
    EXPECT_TRUE(is_json(RawConnection::body(r))) << r.substr(0, 300);
  }
  EXPECT_TRUE(c.closed_by_peer(std::chrono::milliseconds(3000)));
  EXPECT_EQ(handled_, 0);
}

TEST_F(HttpServer, AdmissionRunsBeforeTheBodyIsSent) {
  start();
  // The body is announced and never sent: the refusal must not wait for it.
  const auto r = exchange("POST /x HTTP/1.1\r\nHost: evil\r\nContent-Length: 1000\r\n\r\n");
  EXPECT_EQ(RawConnection::status(r), 403) << r;
  EXPECT_EQ(handled_, 0);
}

TEST_F(HttpServer, InvalidUtf8GetsAValidJsonError) {
  start();
  const auto r = exchange("GET /throw HTTP/1.1\r\nHost: ok\r\n\r\n");
  EXPECT_EQ(RawConnection::status(r), 500) << r;
  EXPECT_TRUE(is_json(RawConnection::body(r))) << r;
  EXPECT_TRUE(is_json(control::http::error_body("node '\xff\xfe' not found")));
}

TEST_F(HttpServer, SilentConnectionsDoNotStarveTheOthersAndAreClosedWhenIdle) {
  start();
  std::vector<std::unique_ptr<RawConnection>> silent;
  for (int i = 0; i < 200; ++i) {
    silent.push_back(std::make_unique<RawConnection>(server_->port()));
    if (i % 2) silent.back()->send("GET /x HTTP/1.1\r\nHo");  // half a request, then nothing
  }
  const auto r = exchange("GET /x HTTP/1.1\r\nHost: ok\r\n\r\n");
  EXPECT_EQ(RawConnection::status(r), 200) << r;
  // The idle timeout (1 s here) closes them.
  EXPECT_TRUE(silent.front()->closed_by_peer(std::chrono::milliseconds(4000)));
  EXPECT_TRUE(silent.back()->closed_by_peer(std::chrono::milliseconds(4000)));
}

TEST_F(HttpServer, RequestsBeyondTheQueueAre503) {
  hold_ = true;  // the workers block: requests pile up
  start();
  std::vector<std::unique_ptr<RawConnection>> clients;
  for (int i = 0; i < 10; ++i) {
    clients.push_back(std::make_unique<RawConnection>(server_->port()));
    clients.back()->send("GET /x HTTP/1.1\r\nHost: ok\r\n\r\n");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // in order: the first reach the workers
  }
  // 2 workers hold 2, 4 wait: the other 4 are refused at once.
  int busy = 0;
  for (auto& c : clients) {
    const auto r = c->receive(std::chrono::milliseconds(300));
    if (RawConnection::status(r) == 503) {
      ++busy;
      EXPECT_TRUE(is_json(RawConnection::body(r)));
    }
  }
  EXPECT_EQ(busy, 4);
  release();
}

}  // namespace
