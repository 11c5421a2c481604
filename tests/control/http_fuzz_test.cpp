// The robustness suite's HTTP part (issue 25): a seeded generator of malformed and abusive
// requests against the reference plant's control plane, in virtual time. After every batch: the
// server still answers, the clock still advances, RSS stays under kRssBoundMb (docs/api.md), and
// the refused requests changed nothing (nodes, faults and the paused clock read the same).
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "engine/running/environment.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"
#include "tests/control/raw_http.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;
using vtest::RawConnection;

constexpr std::uint64_t kSeed = 25;
constexpr int kBatches = 8;
constexpr int kPerBatch = 60;
constexpr long kRssBoundMb = 1024;  // the whole test process, ASan build included

long rss_mb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * (::sysconf(_SC_PAGESIZE) / 1024) / 1024;
}

/// Requests that must all be refused: each is malformed, oversized, foreign or invalid.
class AbuseGenerator {
 public:
  AbuseGenerator(std::uint64_t seed, std::string host) : rng_(seed), host_(std::move(host)) {}

  std::string next() {
    switch (pick(12)) {
      case 0: return bytes(pick(2000));  // noise
      case 1: return "GET /" + std::string(pick(40000), 'a') + " HTTP/1.1\r\nHost: " + host_ + "\r\n\r\n";
      case 2: {  // endless headers
        std::string r = "GET /api/clock HTTP/1.1\r\nHost: " + host_ + "\r\n";
        const auto n = 70 + pick(500);
        for (std::size_t i = 0; i < n; ++i) r += "X-" + std::to_string(i) + ": " + std::string(pick(200), 'v') + "\r\n";
        return r + "\r\n";
      }
      case 3: {  // chunked, over the limit
        std::string r = post_head("/api/nmt") + "Transfer-Encoding: chunked\r\n\r\n";
        for (int i = 0; i < 80; ++i) r += "400\r\n" + std::string(1024, ' ') + "\r\n";
        return r + "0\r\n\r\n";
      }
      case 4: return post_head("/api/nmt") + "Content-Encoding: gzip\r\nContent-Length: 10\r\n\r\n" + bytes(10);
      case 5: return post_head("/api/nmt") + "Transfer-Encoding: chunked\r\n\r\nzz\r\n" + bytes(20) + "\r\n0\r\n\r\n";
      case 6: return "GET /api/clock HTTP/1.1\r\nHost: " + bytes(1 + pick(30)) + "\r\n\r\n";  // foreign/invalid Host
      case 7: return "GET /api/nodes/dsv/sdo?index=0x1000 HTTP/1.1\r\nHost: " + host_ + "\r\nSec-Fetch-Site: cross-site\r\n\r\n";
      case 8: {  // invalid JSON or invalid UTF-8 in a body
        const auto body = pick(2) ? bytes(pick(200)) : "{\"command\":\"" + bytes(8) + "\",\"node\":\"dsv\"}";
        return post_head(endpoint()) + "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
      }
      case 9: {  // well-formed JSON, wrong fields
        const json body = {{"command", "explode"}, {"node", bytes(4)}, {"index", -1}, {"kind", "nope"}, {"action", 7}};
        const auto text = body.dump(-1, ' ', false, json::error_handler_t::replace);
        return post_head(endpoint()) + "Content-Length: " + std::to_string(text.size()) + "\r\n\r\n" + text;
      }
      case 10: return "GET / HTTP/1.1\r\nHost: " + host_ + "\r\nRange: bytes=" + ranges() + "\r\n\r\nPOST";
      default: return std::string(pick(2) ? "BREW" : "DELETE") + " /api/nodes/" + bytes(6) + " HTTP/1.1\r\nHost: " + host_ + "\r\n\r\n";
    }
  }

 private:
  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
  std::string bytes(std::size_t n) {
    std::string s(n, '\0');
    for (auto& c : s) c = static_cast<char>(pick(256));
    return s;
  }
  std::string post_head(const std::string& path) { return "POST " + path + " HTTP/1.1\r\nHost: " + host_ + "\r\n"; }
  std::string endpoint() {
    static const char* const paths[] = {"/api/nmt", "/api/frames", "/api/faults", "/api/clock", "/api/nodes/dsv/sdo",
                                        "/api/nodes/dsv/sdo/read", "/api/nodes/dsv/inputs"};
    return paths[pick(std::size(paths))];
  }
  std::string ranges() {
    std::string r = "0-";
    for (std::size_t i = pick(3000); i > 0; --i) r += ",0-";
    return r;
  }

  std::mt19937_64 rng_;
  std::string host_;
};

/// What a refused request must leave as it was (the clock is paused).
json state(LivePlant& p) {
  return {{"nodes", LivePlant::json_of(p.http().Get("/api/nodes"))},
          {"faults", LivePlant::json_of(p.http().Get("/api/faults"))},
          {"clock", LivePlant::json_of(p.http().Get("/api/clock"))["t_us"]}};
}

TEST(HttpFuzz, AbusiveRequestsAreRefusedAndChangeNothing) {
  LivePlant p(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment());
  p.run_ms(600);  // booted: the nodes have a state to keep
  AbuseGenerator gen(kSeed, "127.0.0.1:" + std::to_string(p.port()));
  for (int batch = 0; batch < kBatches; ++batch) {
    const auto before = state(p);
    for (int i = 0; i < kPerBatch; ++i) {
      const auto request = gen.next();
      RawConnection c(p.port());
      ASSERT_TRUE(c.ok());
      c.send(request);
      const auto r = c.receive(std::chrono::milliseconds(2000));
      const int status = RawConnection::status(r);
      // Answered with a refusal (4xx, or 505 for a garbled version), or the connection closed;
      // never a success or a server error. The Range request is the one allowed success: the
      // whole page, once.
      if (status == 200) {
        EXPECT_NE(r.find("Content-Type: text/html"), std::string::npos) << "batch " << batch << " #" << i;
      } else if (status != -1) {
        EXPECT_GE(status, 400) << r.substr(0, 200);
        EXPECT_LT(status, 506) << r.substr(0, 200);  // 505: an HTTP version other than 1.0/1.1
        // Every refusal, the server's framing checks included, is a JSON error with a reason.
        EXPECT_NE(r.find("Content-Type: application/json"), std::string::npos) << r.substr(0, 300);
        const auto body = json::parse(RawConnection::body(r), nullptr, false);
        EXPECT_TRUE(body.is_object() && body.contains("error")) << r.substr(0, 300);
      }
    }
    EXPECT_EQ(state(p), before) << "batch " << batch;
    EXPECT_LT(rss_mb(), kRssBoundMb);
    const auto t0 = LivePlant::json_of(p.http().Get("/api/clock"))["t_us"].get<std::int64_t>();
    p.run_ms(5);  // the clock still advances
    EXPECT_EQ(LivePlant::json_of(p.http().Get("/api/clock"))["t_us"].get<std::int64_t>(), t0 + 5000);
  }
}

TEST(HttpFuzz, FiveHundredSilentConnectionsDoNotBlockARequest) {
  LivePlant p(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment());
  std::vector<std::unique_ptr<RawConnection>> silent;
  for (int i = 0; i < 500; ++i) {
    silent.push_back(std::make_unique<RawConnection>(p.port()));
    ASSERT_TRUE(silent.back()->ok());
    if (i % 2) silent.back()->send("GET /api/clock HTTP/1.1\r\nHo");  // half a request, then nothing
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = p.http().Get("/api/clock");
  const auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  std::printf("a request with 500 silent connections open: %.1f ms, RSS %ld MB\n", ms, rss_mb());
  ::testing::Test::RecordProperty("latency_ms", std::to_string(ms));
}

}  // namespace
