// The exercise endpoints (control/exercise_endpoints.cpp) on the reference plant in virtual time:
// each shipped exercise solved through the HTTP API with every step done, and the wrong thing done
// with the step left open; selection errors answered with their reasons; the stream's `exercise`
// event on connect, on a selection and when a step is done.
#include <gtest/gtest.h>

#include "engine/running/environment.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;

class ExerciseApi : public ::testing::Test {
 protected:
  void SetUp() override {
    plant_ = std::make_unique<LivePlant>(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment(), 4,
                                         VPLANT_EXERCISES);
    p().run_ms(600);  // every node booted
  }
  LivePlant& p() { return *plant_; }
  json get(const std::string& path) { return LivePlant::json_of(p().http().Get(path.c_str())); }
  static int status(const httplib::Result& r) { return r ? r->status : -1; }
  void select(const std::string& name) {
    const auto r = p().post("/api/exercise", {{"name", name}});
    ASSERT_EQ(status(r), 200) << (r ? r->body : "");
    const auto e = LivePlant::json_of(r);
    EXPECT_EQ(e["name"], name);
    for (const auto& s : e["steps"]) EXPECT_FALSE(s["done"].get<bool>());
  }
  /// The steps done so far (all of them before the first open one).
  std::size_t done_steps() {
    const auto e = get("/api/exercise");
    std::size_t n = 0;
    for (const auto& s : e["steps"]) n += s["done"].get<bool>() ? 1 : 0;
    return n;
  }
  void nmt(const std::string& command, const json& node) {
    ASSERT_EQ(status(p().post("/api/nmt", {{"command", command}, {"node", node}})), 200);
    p().run_ms(20);
  }
  void sdo(const std::string& node, int index, int sub, std::int64_t value) {
    const auto r = p().post("/api/nodes/" + node + "/sdo", {{"index", index}, {"sub", sub}, {"value", value}});
    ASSERT_EQ(status(r), 200);
    ASSERT_TRUE(LivePlant::json_of(r)["ok"].get<bool>()) << r->body;
  }
  json sdo_read(const std::string& node, int index, int sub) {
    const auto r = p().post("/api/nodes/" + node + "/sdo/read", {{"index", index}, {"sub", sub}});
    EXPECT_EQ(status(r), 200);
    p().run_ms(10);
    return LivePlant::json_of(r);
  }
  void input(const std::string& node, const std::string& name, double value) {
    ASSERT_EQ(status(p().post("/api/nodes/" + node + "/inputs", {{"name", name}, {"value", value}})), 200);
    p().run_ms(20);
  }
  void clear_fault(const httplib::Result& injected) {
    const auto id = LivePlant::json_of(injected)["id"].get<int>();
    ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(id)).c_str())), 200);
    p().run_ms(20);
  }
  /// Every step done, each at a virtual time no earlier than the one before.
  void expect_all_done() {
    const auto e = get("/api/exercise");
    EXPECT_TRUE(e["done"].get<bool>()) << e.dump(1);
    std::int64_t last = 0;
    for (const auto& s : e["steps"]) {
      ASSERT_TRUE(s["done"].get<bool>()) << s["title"];
      EXPECT_GE(s["t_us"].get<std::int64_t>(), last);
      last = s["t_us"].get<std::int64_t>();
    }
  }

  std::unique_ptr<LivePlant> plant_;
};

TEST_F(ExerciseApi, ListsTheShippedExercises) {
  const auto names = get("/api/exercises");
  for (const char* want : {"nmt", "heartbeat"}) EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  const auto none = get("/api/exercise");
  EXPECT_TRUE(none["name"].is_null());
  EXPECT_TRUE(none["steps"].empty());
}

/// The data of every `exercise` event in a stream's text, in order.
std::vector<json> exercise_events(const std::string& stream) { return vtest::events_of(stream, "exercise"); }

TEST_F(ExerciseApi, TheStreamSendsTheExerciseOnConnectOnSelectionAndWhenAStepIsDone) {
  vtest::StreamCapture stream(p().port(), "");
  // Waits until the stream holds `n` exercise events; returns them.
  const auto wait_for = [&](std::size_t n) {
    for (int i = 0; i < 150; ++i) {
      if (auto e = exercise_events(stream.text()); e.size() >= n) return e;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return exercise_events(stream.text());
  };
  auto events = wait_for(1);  // on connect: none selected
  ASSERT_EQ(events.size(), 1u);
  EXPECT_TRUE(events[0]["name"].is_null());
  select("nmt");
  events = wait_for(2);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1]["name"], "nmt");
  EXPECT_EQ(events[1]["current"], 0);
  EXPECT_FALSE(events[1]["steps"][0]["done"].get<bool>());
  nmt("start", "dsv");  // step 1 done
  events = wait_for(3);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_TRUE(events[2]["steps"][0]["done"].get<bool>());
  EXPECT_EQ(events[2]["steps"][0]["t_us"], get("/api/exercise")["steps"][0]["t_us"]);
  EXPECT_EQ(events[2]["current"], 1);
  nmt("start", "md2");  // no step done: no event
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(wait_for(3).size(), 3u);
}

TEST_F(ExerciseApi, BadSelectionsAreRefusedWithAReason) {
  EXPECT_EQ(status(p().post("/api/exercise", {{"name", "no-such"}})), 404);
  EXPECT_EQ(status(p().post("/api/exercise", {{"name", "../CMakeLists"}})), 400);
  EXPECT_EQ(status(p().post("/api/exercise", {{"name", {1, 2}}})), 400);
  EXPECT_EQ(status(p().post("/api/exercise", {{"nam", "nmt"}})), 400);
  const auto extra = p().post("/api/exercise", {{"name", "nmt"}, {"step", 2}});
  EXPECT_EQ(status(extra), 400);
  EXPECT_NE(LivePlant::json_of(extra)["error"].get<std::string>().find("unknown key 'step'"), std::string::npos);
  EXPECT_EQ(status(p().http().Post("/api/exercise", "[", "application/json")), 400);
  const auto r = p().post("/api/exercise", {{"name", "no-such"}});
  EXPECT_NE(LivePlant::json_of(r)["error"].get<std::string>().find("no exercise 'no-such'"), std::string::npos);
  EXPECT_TRUE(get("/api/exercise")["name"].is_null());  // nothing changed
}

TEST_F(ExerciseApi, NmtSolved) {
  select("nmt");
  nmt("start", "dsv");
  EXPECT_EQ(done_steps(), 1u);
  const auto e = get("/api/exercise");
  EXPECT_GT(e["steps"][0]["t_us"].get<std::int64_t>(), 600000);
  EXPECT_TRUE(e["steps"][1]["t_us"].is_null());
  EXPECT_EQ(e["current"], 1);
  nmt("stop", "dsv");
  nmt("pre_operational", "dsv");
  EXPECT_EQ(done_steps(), 3u);
  nmt("reset_communication", "dsv");
  p().run_ms(100);
  EXPECT_EQ(done_steps(), 4u);
  nmt("start", 0);
  expect_all_done();
}

TEST_F(ExerciseApi, NmtStartingTheWrongNodeLeavesTheStepOpen) {
  select("nmt");
  nmt("start", "md2");
  nmt("stop", "dsv");
  EXPECT_EQ(done_steps(), 0u);
  EXPECT_EQ(get("/api/exercise")["current"], 0);
}

TEST_F(ExerciseApi, HeartbeatSolved) {
  select("heartbeat");
  sdo("dsv", 0x1017, 0, 100);
  p().run_ms(250);
  EXPECT_EQ(done_steps(), 1u);
  sdo("wdga", 0x1016, 1, 0x000201F4);
  p().run_ms(250);
  EXPECT_EQ(done_steps(), 2u);
  const auto f = p().post("/api/faults", {{"drop", {{"id", "0x702"}}}});
  ASSERT_EQ(status(f), 200);
  p().run_ms(1000);
  EXPECT_EQ(done_steps(), 3u);
  clear_fault(f);
  p().run_ms(480);
  expect_all_done();
}

TEST_F(ExerciseApi, HeartbeatWatchingTheWrongNodeLeavesTheStepOpen) {
  select("heartbeat");
  sdo("dsv", 0x1017, 0, 100);
  p().run_ms(250);
  sdo("wdga", 0x1016, 1, 0x000301F4);  // node 3, the MD2, which sends no heartbeat
  p().run_ms(1000);
  EXPECT_EQ(done_steps(), 1u);
}

TEST_F(ExerciseApi, Cia406Solved) {
  select("cia406");
  nmt("start", "wdga");
  EXPECT_EQ(done_steps(), 1u);
  sdo("wdga", 0x6003, 0, 100000);
  p().run_ms(20);
  EXPECT_EQ(done_steps(), 2u);
  EXPECT_EQ(sdo_read("wdga", 0x6400, 1)["value"], 2);  // above the default high limit
  EXPECT_EQ(done_steps(), 2u);
  sdo("wdga", 0x6402, 1, 200000);
  EXPECT_EQ(sdo_read("wdga", 0x6400, 1)["value"], 0);
  EXPECT_EQ(done_steps(), 3u);
  ASSERT_EQ(status(p().post("/api/faults", {{"device_fault", {{"node", "wdga"}, {"fault", "position_error"}}}})), 200);
  p().run_ms(20);
  EXPECT_EQ(sdo_read("wdga", 0x6503, 0)["value"], 1);
  expect_all_done();
}

TEST_F(ExerciseApi, Cia406WrongPresetAndLimitLeaveTheStepsOpen) {
  select("cia406");
  nmt("start", "wdga");
  sdo("wdga", 0x6003, 0, 10000);  // another value than the step asks for
  p().run_ms(20);
  EXPECT_EQ(done_steps(), 1u);
  sdo("wdga", 0x6003, 0, 100000);
  p().run_ms(20);
  sdo("wdga", 0x6402, 1, 200000);
  sdo("wdga", 0x6401, 1, 150000);  // the low limit above the position too: 04h, below
  EXPECT_EQ(sdo_read("wdga", 0x6400, 1)["value"], 4);
  EXPECT_EQ(done_steps(), 2u);
}

TEST_F(ExerciseApi, VtvpcdSolved) {
  select("vtvpcd");
  input("vtvpcd", "enable", 0);
  EXPECT_EQ(get("/api/nodes/vtvpcd")["device"]["state"], "NOT_ENABLED");
  input("vtvpcd", "enable", 1);
  EXPECT_EQ(done_steps(), 2u);
  const auto f = p().post("/api/faults", {{"device_fault", {{"node", "vtvpcd"}, {"fault", "pressure_a_sensor_break"}}}});
  ASSERT_EQ(status(f), 200);
  p().run_ms(20);
  EXPECT_EQ(get("/api/nodes/vtvpcd")["device"]["state"], "FAULT_STOP");
  EXPECT_EQ(done_steps(), 3u);
  clear_fault(f);
  EXPECT_EQ(get("/api/nodes/vtvpcd")["device"]["state"], "FAULT_STOP");  // latched
  EXPECT_EQ(done_steps(), 3u);
  input("vtvpcd", "enable", 0);
  input("vtvpcd", "enable", 1);
  EXPECT_EQ(get("/api/nodes/vtvpcd")["device"]["state"], "RUNNING");
  expect_all_done();
}

TEST_F(ExerciseApi, VtvpcdAnEdgeBeforeTheFaultIsMendedAcknowledgesNothing) {
  select("vtvpcd");
  input("vtvpcd", "enable", 0);
  input("vtvpcd", "enable", 1);
  const auto f = p().post("/api/faults", {{"device_fault", {{"node", "vtvpcd"}, {"fault", "pressure_a_sensor_break"}}}});
  ASSERT_EQ(status(f), 200);
  p().run_ms(20);
  input("vtvpcd", "enable", 0);
  input("vtvpcd", "enable", 1);
  clear_fault(f);
  EXPECT_EQ(get("/api/nodes/vtvpcd")["device"]["state"], "FAULT_STOP");
  EXPECT_EQ(done_steps(), 3u);
}

TEST_F(ExerciseApi, Dsp408Solved) {
  select("dsp408");
  for (const int cw : {0x0001, 0x0003, 0x0007}) {
    sdo("dsv", 0x6040, 0, cw);
    p().run_ms(20);
  }
  EXPECT_EQ(done_steps(), 3u);
  sdo("dsv", 0x6040, 0, 0x0000);
  p().run_ms(20);
  EXPECT_EQ(done_steps(), 4u);
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(20);
  EXPECT_EQ(done_steps(), 5u);
  nmt("start", "dsv");
  nmt("stop", "dsv");
  expect_all_done();
}

TEST_F(ExerciseApi, Dsp408PullingTheEnableInputIsNotTheControlWordPath) {
  select("dsp408");
  for (const int cw : {0x0001, 0x0003, 0x0007}) {
    sdo("dsv", 0x6040, 0, cw);
    p().run_ms(20);
  }
  input("dsv", "enable_input", 0);
  EXPECT_EQ(done_steps(), 3u);
}

TEST_F(ExerciseApi, SelectingAgainStartsOver) {
  select("nmt");
  nmt("start", "dsv");
  EXPECT_EQ(done_steps(), 1u);
  select("nmt");
  EXPECT_EQ(done_steps(), 0u);
}

}  // namespace
