// The control plane's limits and checks against the reference plant (issue 25): cross-site and
// state-changing GET requests refused, invalid UTF-8 answered with JSON, no Range amplification,
// the clock speed's range, a prompt stop at the slowest speed, frames the bus refused reported,
// the command queue's bound.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "control/sim_bridge.h"
#include "engine/running/environment.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"
#include "tests/control/raw_http.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;
using vtest::RawConnection;

scenario::Scenario reference_plant() { return scenario::load_scenario_file(VPLANT_REFERENCE_PLANT); }
bool is_json(const std::string& body) { return !json::parse(body, nullptr, false).is_discarded(); }

class ControlLimits : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { plant_ = new LivePlant(reference_plant(), scenario::default_environment()); }
  static void TearDownTestSuite() {
    delete plant_;
    plant_ = nullptr;
  }
  LivePlant& p() { return *plant_; }
  std::int64_t t_us() { return LivePlant::json_of(p().http().Get("/api/clock"))["t_us"].get<std::int64_t>(); }
  std::string host() const { return "127.0.0.1:" + std::to_string(plant_->port()); }
  std::string raw(const std::string& request) {
    RawConnection c(p().port());
    c.send(request);
    return c.receive();
  }

  static LivePlant* plant_;
};
LivePlant* ControlLimits::plant_ = nullptr;

TEST_F(ControlLimits, CrossSiteRequestsAreRefused) {
  for (const char* site : {"cross-site", "same-site"}) {
    const auto r = p().http().Get("/api/clock", {{"Sec-Fetch-Site", site}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 403) << site;
    EXPECT_TRUE(is_json(r->body));
  }
  EXPECT_EQ(p().http().Get("/api/clock", {{"Sec-Fetch-Site", "same-origin"}})->status, 200);
  EXPECT_EQ(p().http().Get("/api/clock", {{"Sec-Fetch-Site", "none"}})->status, 200);
}

TEST_F(ControlLimits, SdoUploadIsNotAGetRequest) {
  const auto t0 = t_us();
  const auto r = p().http().Get("/api/nodes/dsv/sdo?index=0x1000&sub=0");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 405);
  EXPECT_NE(r->body.find("POST"), std::string::npos) << r->body;
  EXPECT_EQ(p().http().Get("/api/nodes/dsv/sdo/read?index=0x1000")->status, 405);
  EXPECT_EQ(t_us(), t0);  // no transfer ran: the paused clock did not move
}

TEST_F(ControlLimits, InvalidUtf8GetsAJson4xx) {
  const std::string bad = "\xff\xfe\xc3";
  for (const auto& request : {
           "GET /api/nodes/%FF%FE HTTP/1.1\r\nHost: " + host() + "\r\n\r\n",
           "GET /api/signals?names=%FF HTTP/1.1\r\nHost: " + host() + "\r\n\r\n",
           "GET /api/clock HTTP/1.1\r\nHost: " + bad + "\r\n\r\n",
           "GET /api/clock HTTP/1.1\r\nHost: " + host() + "\r\nOrigin: http://" + bad + "\r\n\r\n",
           "POST /api/nodes/" + bad + "/inputs HTTP/1.1\r\nHost: " + host() + "\r\nContent-Length: 27\r\n\r\n{\"name\":\"x\",\"value\":1.0000}",
       }) {
    const auto r = raw(request);
    const int status = RawConnection::status(r);
    EXPECT_GE(status, 400) << request;
    EXPECT_LT(status, 500) << request;
    EXPECT_TRUE(is_json(RawConnection::body(r))) << r;
  }
}

TEST_F(ControlLimits, RangeIsIgnored) {
  std::string ranges = "bytes=0-";
  for (int i = 0; i < 500; ++i) ranges += ",0-";
  const auto whole = p().http().Get("/");
  const auto ranged = p().http().Get("/", {{"Range", ranges}});
  ASSERT_TRUE(whole && ranged);
  EXPECT_NE(ranged->status, 206);
  EXPECT_EQ(ranged->body.size(), whole->body.size());
}

TEST_F(ControlLimits, ClockSpeedHasARangeThatMeansWhatItSays) {
  for (const double speed : {1e-14, 0.0009, 1001.0, -1.0}) {
    const auto r = p().post("/api/clock", {{"action", "resume"}, {"speed", speed}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << speed;
    EXPECT_TRUE(is_json(r->body));
  }
  EXPECT_TRUE(LivePlant::json_of(p().http().Get("/api/clock"))["paused"].get<bool>());
}

TEST_F(ControlLimits, FramesTheBusRefusesAreReportedAsRefused) {
  // Paused, the bit-timed bus sends nothing: the control plane's transmit queue fills up.
  int queued = 0, refused = 0;
  for (int i = 0; i < 40; ++i) {
    const auto r = p().post("/api/frames", {{"id", 0x7E5}, {"data", "01"}});
    ASSERT_TRUE(r);
    if (r->status == 200) {
      EXPECT_EQ(json::parse(r->body)["queued"], true);
      ++queued;
    } else {
      EXPECT_EQ(r->status, 503) << r->body;
      EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("queue"), std::string::npos);
      ++refused;
    }
  }
  EXPECT_GT(queued, 0);
  EXPECT_GT(refused, 0);
  p().run_ms(20);  // the queue drains at the bus's rate
  EXPECT_EQ(p().post("/api/frames", {{"id", 0x7E5}, {"data", "01"}})->status, 200);
}

TEST_F(ControlLimits, ActiveFaultsAreBounded) {
  std::vector<int> ids;
  int status = 200;
  for (int i = 0; i < 300 && status == 200; ++i) {
    const auto r = p().post("/api/faults", {{"drop", {{"id", "0x7E0"}}}});
    ASSERT_TRUE(r);
    status = r->status;
    if (status == 200) ids.push_back(json::parse(r->body)["id"].get<int>());
    else EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("too many active faults"), std::string::npos);
  }
  EXPECT_EQ(status, 429);
  EXPECT_EQ(ids.size(), 256u);
  for (const int id : ids) EXPECT_EQ(p().http().Delete(("/api/faults/" + std::to_string(id)).c_str())->status, 200);
  EXPECT_TRUE(LivePlant::json_of(p().http().Get("/api/faults")).empty());
}

/// Simultaneous POST /api/faults from more clients than there are workers: the bound holds exactly
/// (the check and the insert used to be two commands, so requests passing the check together all
/// inserted), and the faults are never more than the bound.
TEST(ControlFaultBound, ConcurrentInjectionsNeverPassTheBound) {
  LivePlant p(reference_plant(), scenario::default_environment());
  constexpr int kClients = 24, kEach = 16;  // 384 requests for 256 places
  for (int round = 0; round < 4; ++round) {  // the race was a matter of timing: several rounds
    std::atomic<int> accepted{0}, refused{0}, other{0};
    std::vector<std::thread> clients;
    for (int t = 0; t < kClients; ++t)
      clients.emplace_back([&] {
        httplib::Client c("127.0.0.1", p.port());
        for (int i = 0; i < kEach; ++i) {
          const auto r = c.Post("/api/faults", json{{"drop", {{"id", "0x7E0"}}}}.dump(), "application/json");
          if (r && r->status == 200) ++accepted;
          else if (r && r->status == 429 && r->body.find("too many active faults") != std::string::npos) ++refused;
          else ++other;
        }
      });
    for (auto& c : clients) c.join();
    EXPECT_EQ(other, 0) << "round " << round;
    EXPECT_EQ(accepted, 256) << "round " << round;
    EXPECT_EQ(refused, kClients * kEach - 256) << "round " << round;
    const auto active = LivePlant::json_of(p.http().Get("/api/faults"));
    ASSERT_EQ(active.size(), 256u) << "round " << round;
    // Clearing one frees exactly one place.
    EXPECT_EQ(p.http().Delete(("/api/faults/" + std::to_string(active[0]["id"].get<int>())).c_str())->status, 200);
    EXPECT_EQ(p.post("/api/faults", {{"drop", {{"id", "0x7E0"}}}})->status, 200);
    EXPECT_EQ(p.post("/api/faults", {{"drop", {{"id", "0x7E0"}}}})->status, 429);
    for (const auto& f : LivePlant::json_of(p.http().Get("/api/faults")))
      EXPECT_EQ(p.http().Delete(("/api/faults/" + std::to_string(f["id"].get<int>())).c_str())->status, 200);
  }
}

TEST(ControlStop, ARunStopsPromptlyAtTheSlowestSpeed) {
  LivePlant p(reference_plant(), scenario::default_environment());
  // 0.001 × wall clock: one 1 ms tick takes a wall second.
  ASSERT_EQ(p.post("/api/clock", {{"action", "resume"}, {"speed", control::kMinSpeed}})->status, 200);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto took = p.stop();
  EXPECT_LT(took.count(), 500);  // was up to a wall second per tick (1,000 s at speed 1e-6)
  EXPECT_EQ(p.exit_code(), 0);
}

TEST(ControlQueue, CommandsBeyondTheBoundAreRefused) {
  control::SimBridge bridge(control::ClockOptions{});
  std::size_t queued = 0;
  for (std::size_t i = 0; i < control::kMaxQueuedCommands + 10; ++i)
    queued += bridge.try_post([](const scenario::RunContext&) {}) == control::SimBridge::Posted::Queued;
  EXPECT_EQ(queued, control::kMaxQueuedCommands);
  EXPECT_EQ(bridge.try_post([](const scenario::RunContext&) {}), control::SimBridge::Posted::Full);
}

}  // namespace
