// The controls a lesson needs (docs/api.md, "Lesson controls") against the reference plant in
// virtual time: the SYNC producer, the RPDO sender by mapped values, the PDO mapping decode.
#include <gtest/gtest.h>

#include "engine/running/environment.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;

class LessonApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    plant_ = new LivePlant(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment());
  }
  static void TearDownTestSuite() {
    delete plant_;
    plant_ = nullptr;
  }
  LivePlant& p() { return *plant_; }
  json get(const std::string& path) { return LivePlant::json_of(p().http().Get(path.c_str())); }
  static int status(const httplib::Result& r) { return r ? r->status : -1; }
  std::string error_of(const httplib::Result& r) { return LivePlant::json_of(r).value("error", ""); }
  void start_all() {
    if (get("/api/nodes/dsv")["nmt"] == "OPERATIONAL") return;
    p().run_ms(600);
    ASSERT_EQ(status(p().post("/api/nmt", {{"command", "start"}, {"node", 0}})), 200);
    p().run_ms(20);
  }
  /// Stream text received while `during` runs.
  std::string stream_during(const std::string& query, const std::function<void()>& during, const std::string& until) {
    vtest::StreamCapture stream(p().port(), query);
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    during();
    for (int i = 0; i < 150 && stream.text().find(until) == std::string::npos; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    stream.stop();
    return stream.text();
  }

  static LivePlant* plant_;
};
LivePlant* LessonApi::plant_ = nullptr;

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST_F(LessonApi, PdosListEveryRpdoAndTpdoWithItsMappingDecoded) {
  const auto pdos = get("/api/nodes/dsv/pdos");
  ASSERT_TRUE(pdos.is_array());
  const json* rpdo1 = nullptr;
  const json* tpdo1 = nullptr;
  for (const auto& p : pdos) {
    if (p["kind"] == "rpdo" && p["number"] == 1) rpdo1 = &p;
    if (p["kind"] == "tpdo" && p["number"] == 1) tpdo1 = &p;
  }
  ASSERT_TRUE(rpdo1 && tpdo1) << pdos.dump();
  EXPECT_EQ((*rpdo1)["cob_id"], 0x202);
  EXPECT_EQ((*rpdo1)["valid"], true);
  EXPECT_TRUE((*rpdo1)["transmission_type"].is_number());
  ASSERT_FALSE((*rpdo1)["entries"].empty());
  EXPECT_EQ((*rpdo1)["entries"][0]["object"], "6040:00");
  EXPECT_EQ((*rpdo1)["entries"][0]["raw"], "0x60400010");
  EXPECT_EQ((*rpdo1)["entries"][0]["bits"], 16);
  EXPECT_EQ((*rpdo1)["entries"][0]["name"], "Device control word");
  EXPECT_EQ((*tpdo1)["cob_id"], 0x182);
  ASSERT_FALSE((*tpdo1)["entries"].empty());
  EXPECT_EQ((*tpdo1)["entries"][0]["object"], "6041:00");
  EXPECT_EQ((*tpdo1)["entries"][0]["name"], "Device status word");
  EXPECT_EQ(status(p().http().Get("/api/nodes/ghost/pdos")), 404);
}

TEST_F(LessonApi, PdosFollowTheMappingTheNodeHoldsNow) {
  start_all();
  // Pre-operational: the mapping may change (CiA 301: count 0, entry, count).
  ASSERT_EQ(status(p().post("/api/nmt", {{"command", "pre_operational"}, {"node", "md2"}})), 200);
  p().run_ms(5);
  const auto write = [&](int index, int sub, std::int64_t value) {
    auto r = LivePlant::json_of(p().post("/api/nodes/md2/sdo", {{"index", index}, {"sub", sub}, {"value", value}}));
    EXPECT_EQ(r["ok"], true) << index << ":" << sub << " " << r.dump();
  };
  write(0x1400, 1, 0x80000203);  // the PDO invalid while its mapping changes
  write(0x1600, 0, 0);
  write(0x1600, 1, 0x60400010);
  write(0x1600, 0, 1);
  write(0x1400, 1, 0x203);
  const auto pdos = get("/api/nodes/md2/pdos");
  for (const auto& p : pdos)
    if (p["kind"] == "rpdo" && p["number"] == 1) {
      ASSERT_EQ(p["entries"].size(), 1u) << p.dump();
      EXPECT_EQ(p["entries"][0]["object"], "6040:00");
    }
  // The RPDO sender lays the frame out as the node holds it now: one UNSIGNED16.
  const auto r = LivePlant::json_of(p().post("/api/nodes/md2/rpdo", {{"pdo", 1}, {"values", {{"6040:00", 6}}}}));
  EXPECT_EQ(r["ok"], true) << r.dump();
  EXPECT_EQ(r["id"], 0x203);
  EXPECT_EQ(r["data"], "0600");
  ASSERT_EQ(status(p().post("/api/nmt", {{"command", "reset_communication"}, {"node", "md2"}})), 200);
  p().run_ms(20);
  ASSERT_EQ(status(p().post("/api/nmt", {{"command", "start"}, {"node", "md2"}})), 200);
  p().run_ms(5);
}

TEST_F(LessonApi, RpdoByMappedValuesDrivesTheDsv) {
  start_all();
  auto r = p().post("/api/nodes/dsv/rpdo", {{"pdo", 1}, {"values", {{"6040:00", 7}, {"6300:01", 0}}}});
  ASSERT_EQ(status(r), 200) << r->body;
  EXPECT_EQ(LivePlant::json_of(r)["id"], 0x202);
  EXPECT_EQ(LivePlant::json_of(r)["data"], "07000000");
  p().run_ms(30);
  EXPECT_EQ(get("/api/nodes/dsv")["device"]["state"], "DEVICE_MODE_ACTIVE");
  r = p().post("/api/nodes/dsv/rpdo", {{"pdo", 1}, {"values", {{"0x6040:00", 0}, {"6300:01", -1}}}});
  ASSERT_EQ(status(r), 200) << r->body;
  p().run_ms(30);
  EXPECT_NE(get("/api/nodes/dsv")["device"]["state"], "DEVICE_MODE_ACTIVE");
}

TEST_F(LessonApi, RpdoRefusalsSayWhy) {
  const auto post = [&](const json& body) { return p().post("/api/nodes/dsv/rpdo", body); };
  auto r = post({{"pdo", 1}, {"values", {{"6040:00", 7}}}});
  EXPECT_EQ(status(r), 400);
  EXPECT_NE(error_of(r).find("0x6300:01 is mapped but not given"), std::string::npos) << error_of(r);
  r = post({{"pdo", 1}, {"values", {{"6040:00", 7}, {"6300:01", 0}, {"6041:00", 1}}}});
  EXPECT_EQ(status(r), 400);
  EXPECT_NE(error_of(r).find("0x6041:00 is not mapped"), std::string::npos) << error_of(r);
  r = post({{"pdo", 1}, {"values", {{"6040:00", 70000}, {"6300:01", 0}}}});
  EXPECT_EQ(status(r), 400);
  EXPECT_NE(error_of(r).find("0x6040:00"), std::string::npos) << error_of(r);
  r = post({{"pdo", 9}, {"values", json::object()}});
  EXPECT_EQ(status(r), 400);
  EXPECT_NE(error_of(r).find("the node has no such RPDO"), std::string::npos) << error_of(r);
  EXPECT_EQ(status(post({{"pdo", 0}, {"values", json::object()}})), 400);
  EXPECT_EQ(status(post({{"pdo", 1}})), 400);
  EXPECT_EQ(status(post({{"pdo", 1}, {"values", {{"banana", 1}}}})), 400);
  EXPECT_EQ(status(post({{"pdo", 1}, {"values", {{"6040:00", json::array()}, {"6300:01", 0}}}})), 400);
  EXPECT_EQ(status(p().post("/api/nodes/ghost/rpdo", {{"pdo", 1}, {"values", json::object()}})), 404);
}

TEST_F(LessonApi, SyncProducerRunsBetweenTicksAndStops) {
  start_all();
  EXPECT_EQ(get("/api/sync")["period_ms"], 0);
  const auto on = [&] {
    auto r = LivePlant::json_of(p().post("/api/sync", {{"period_ms", 10}}));
    EXPECT_EQ(r["period_ms"], 10);
    EXPECT_EQ(r["bus"], "main");
    p().run_ms(100);
  };
  const auto stream = stream_during("", on, "never");
  // 100 ms at 10 ms: 10 SYNCs (the first at once), on the bus as candump lines.
  EXPECT_EQ(count_of(stream, " main 080#\""), 10u) << stream.substr(0, 3000);
  EXPECT_EQ(get("/api/sync")["period_ms"], 10);

  const auto counter = [&] {
    EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", 5}, {"counter_overflow", 3}})), 200);
    p().run_ms(15);
  };
  const auto counted = stream_during("", counter, "never");
  EXPECT_EQ(count_of(counted, " main 080#01\""), 1u) << counted.substr(0, 3000);
  EXPECT_EQ(count_of(counted, " main 080#02\""), 1u);
  EXPECT_EQ(count_of(counted, " main 080#03\""), 1u);

  const auto off = [&] {
    EXPECT_EQ(LivePlant::json_of(p().post("/api/sync", {{"period_ms", 0}}))["period_ms"], 0);
    p().run_ms(50);
  };
  EXPECT_EQ(count_of(stream_during("", off, "never"), " main 080#"), 0u);
}

TEST_F(LessonApi, SyncRefusalsSayWhy) {
  EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", -1}})), 400);
  EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", 60001}})), 400);
  EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", "ten"}})), 400);
  EXPECT_EQ(status(p().post("/api/sync", json::object())), 400);
  EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", 10}, {"counter_overflow", 1}})), 400);
  EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", 10}, {"counter_overflow", 241}})), 400);
  EXPECT_EQ(status(p().post("/api/sync", {{"period_ms", 10}, {"bus", "can9"}})), 404);
  EXPECT_EQ(status(p().http().Get("/api/sync?bus=can9")), 404);
  EXPECT_EQ(get("/api/sync")["period_ms"], 0);
}

}  // namespace

namespace {

/// POST /api/restart on a plant of its own (virtual or real time).
class LessonRestart : public ::testing::TestWithParam<bool> {};

TEST_P(LessonRestart, RebuildsTheScenarioAtTimeZeroAndEveryNodeBootsAgain) {
  auto s = scenario::load_scenario_file(VPLANT_REFERENCE_PLANT);
  const bool realtime = GetParam();
  if (realtime) s.clock.mode = scenario::ClockSpec::Mode::RealTime;
  LivePlant p(std::move(s), scenario::default_environment());
  const auto get = [&](const std::string& path) { return LivePlant::json_of(p.http().Get(path.c_str())); };
  const auto wait_for_nmt = [&](const std::string& nmt) {
    for (int i = 0; i < 400 && get("/api/nodes/hlt")["nmt"] != nmt; ++i) {
      if (!realtime) p.run_ms(10);
      else std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return get("/api/nodes/hlt")["nmt"] == nmt;
  };
  ASSERT_TRUE(wait_for_nmt("PRE-OPERATIONAL"));
  ASSERT_EQ(p.post("/api/nmt", {{"command", "start"}, {"node", 0}})->status, 200);
  ASSERT_TRUE(wait_for_nmt("OPERATIONAL"));
  ASSERT_EQ(p.post("/api/sync", {{"period_ms", 10}})->status, 200);
  const auto before = get("/api/clock")["t_us"].get<std::int64_t>();
  EXPECT_GT(before, 0);

  std::string stream;
  std::mutex mu;
  std::atomic<bool> stop{false};
  httplib::Client sse("127.0.0.1", p.port());
  sse.set_read_timeout(5, 0);
  std::thread reader([&] {
    sse.Get("/api/events", [&](const char* data, std::size_t n) {
      std::lock_guard lk(mu);
      stream.append(data, n);
      return !stop.load();
    });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  const auto r = p.post("/api/restart", json::object());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto answer = LivePlant::json_of(r);
  EXPECT_LT(answer["clock"]["t_us"].get<std::int64_t>(), realtime ? 500000 : 1);
  if (!realtime) {
    EXPECT_TRUE(answer["clock"]["paused"].get<bool>());  // as it was
  }
  EXPECT_EQ(get("/api/sync")["period_ms"], 0);                     // the lesson's SYNC is off again
  ASSERT_TRUE(wait_for_nmt("PRE-OPERATIONAL"));                     // booted again
  if (!realtime) p.run_ms(600);                                     // the slowest boot-up too
  for (int i = 0; i < 100; ++i) {
    {
      std::lock_guard lk(mu);
      if (stream.find(" main 77F#00") != std::string::npos && stream.find(" main 73F#00") != std::string::npos) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  stop = true;
  reader.join();
  EXPECT_NE(stream.find("event: restart"), std::string::npos);
  // Every node's boot-up after the restart.
  const auto restart_at = stream.find("event: restart");
  for (const char* boot : {" main 73F#00", " main 702#00", " main 703#00", " main 705#00", " main 77F#00"})
    EXPECT_NE(stream.find(boot, restart_at), std::string::npos) << boot;
  // Restarted again at once: still answers.
  ASSERT_EQ(p.post("/api/restart", json::object())->status, 200);
  EXPECT_EQ(p.stop().count() >= 0, true);
  EXPECT_EQ(p.exit_code(), 0);
}

INSTANTIATE_TEST_SUITE_P(Clock, LessonRestart, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "RealTime" : "Virtual"; });

}  // namespace

namespace {

TEST(LessonStream, CarriesTheSelectedNodesDictionaryAsDeltasFaultsAndSharesBeyondFourViewers) {
  LivePlant p(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment(), 2);
  vtest::StreamCapture a(p.port(), "?node=dsv");
  vtest::StreamCapture b(p.port(), "");
  ASSERT_TRUE(a.wait_for("event: od"));
  EXPECT_TRUE(a.wait_for("\"full\":true"));
  EXPECT_NE(a.text().find("\"6040:00\":"), std::string::npos);
  EXPECT_NE(a.text().find("\"node\":\"dsv\""), std::string::npos);
  EXPECT_NE(a.text().find("event: hello"), std::string::npos);
  EXPECT_TRUE(a.wait_for("event: faults"));
  // A delta: only what changed (the control word written by SDO).
  ASSERT_EQ(p.post("/api/nodes/dsv/sdo", {{"index", 0x6040}, {"value", 1}})->status, 200);
  EXPECT_TRUE(a.wait_for("\"full\":false,\"node\":\"dsv\""));
  const auto text = a.text();
  const auto delta = text.find("\"full\":false");
  const auto end = text.find("\n", delta);
  EXPECT_NE(text.substr(delta, end - delta).find("\"6040:00\":1"), std::string::npos) << text.substr(delta, end - delta);
  EXPECT_EQ(text.substr(delta, end - delta).find("\"1000:00\""), std::string::npos);  // unchanged: not sent

  // b chooses a node by its stream id.
  ASSERT_TRUE(b.wait_for("event: hello"));
  const auto hello = b.text();
  const auto at = hello.find("\"stream\":") + 9;
  const auto id = std::stoull(hello.substr(at));
  auto r = p.post("/api/events/node", {{"stream", id}, {"node", "hlt"}});
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_TRUE(b.wait_for("\"node\":\"hlt\""));
  EXPECT_EQ(p.post("/api/events/node", {{"stream", 999}, {"node", "hlt"}})->status, 404);
  EXPECT_EQ(p.post("/api/events/node", {{"stream", id}, {"node", "ghost"}})->status, 404);
  EXPECT_EQ(p.post("/api/events/node", {{"stream", id}})->status, 400);
  EXPECT_EQ(p.http().Get("/api/events?node=ghost")->status, 404);

  // Beyond max_streams (2 here): a shared read-only stream, not a refusal.
  vtest::StreamCapture shared(p.port(), "?node=dsv&signals=cyl.position");
  ASSERT_TRUE(shared.wait_for("\"shared\":true"));
  EXPECT_TRUE(shared.wait_for("event: nodes"));
  p.run_ms(50);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(shared.text().find("event: od"), std::string::npos);
  EXPECT_EQ(shared.text().find("event: signals"), std::string::npos);
  const auto shared_hello = shared.text();
  const auto sid = std::stoull(shared_hello.substr(shared_hello.find("\"stream\":") + 9));
  EXPECT_EQ(p.post("/api/events/node", {{"stream", sid}, {"node", "hlt"}})->status, 404);
}

}  // namespace
