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

TEST_F(HttpServer, ChunkedBodyWithinTheLimitReachesTheHandler) {
  start();
  const auto r = exchange(chunked_post(768));
  EXPECT_EQ(RawConnection::status(r), 200) << r;
  EXPECT_EQ(nlohmann::json::parse(RawConnection::body(r))["bytes"], 768);
}

TEST_F(HttpServer, ChunkedBodyOverTheLimitIs413AndNeverHandled) {
  start();
  const auto r = exchange(chunked_post(4096));
  EXPECT_EQ(RawConnection::status(r), 413) << r;
  EXPECT_TRUE(is_json(RawConnection::body(r)));
  // Far over the limit: the connection is closed without reading it all.
  RawConnection big(server_->port());
  big.send(chunked_post(1 << 20));
  EXPECT_TRUE(big.closed_by_peer(std::chrono::milliseconds(3000)));
  EXPECT_EQ(handled_, 0);
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
  // Answered 431 (or closed) once the header block passes the connection's memory bound.
  EXPECT_TRUE(refused || RawConnection::status(r) == 431 || r.empty()) << r.substr(0, 200);
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
