// `--ui [ADDR:]PORT` parsing, the loopback rule, the scenario's `ui:` key, and real time (where the
// clock cannot be controlled).
#include <gtest/gtest.h>

#include "control/control_plane.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"
#include "tests/engine/test_world.h"

namespace {

TEST(UiOptions, ParsesPortAndAddress) {
  control::UiOptions u;
  EXPECT_EQ(control::parse_ui_address("8080", u), "");
  EXPECT_EQ(u.address, "127.0.0.1");
  EXPECT_EQ(u.port, 8080);
  EXPECT_EQ(control::parse_ui_address("0.0.0.0:9000", u), "");
  EXPECT_EQ(u.address, "0.0.0.0");
  EXPECT_EQ(u.port, 9000);
  EXPECT_EQ(control::parse_ui_address("localhost:81", u), "");
  EXPECT_EQ(u.address, "127.0.0.1");
  EXPECT_NE(control::parse_ui_address("99999", u), "");
  EXPECT_NE(control::parse_ui_address("80a", u), "");
  EXPECT_NE(control::parse_ui_address("", u), "");
  EXPECT_NE(control::parse_ui_address("example.com:80", u), "");
  EXPECT_TRUE(control::is_loopback("127.0.0.1"));
  EXPECT_TRUE(control::is_loopback("127.1.2.3"));
  EXPECT_FALSE(control::is_loopback("0.0.0.0"));
  EXPECT_FALSE(control::is_loopback("192.168.1.10"));
}

TEST(UiOptions, NonLoopbackNeedsAllowRemote) {
  control::UiOptions u;
  u.address = "0.0.0.0";
  u.out = nullptr;
  control::ControlPlane refused(u);
  EXPECT_NE(refused.bind().find("--ui-allow-remote"), std::string::npos);
  u.allow_remote = true;
  control::ControlPlane allowed(u);
  EXPECT_EQ(allowed.bind(), "");
  EXPECT_GT(allowed.port(), 0);
}

TEST(UiOptions, ScenarioKey) {
  auto s = scenario::parse_scenario("ui: 8080\n", "t.yaml", ".");
  EXPECT_EQ(s.ui.listen, "8080");
  EXPECT_TRUE(s.ui.start_paused);
  s = scenario::parse_scenario("ui: {listen: \"127.0.0.1:8081\", start: running, speed: 0, allow_remote: false}\n", "t.yaml", ".");
  EXPECT_EQ(s.ui.listen, "127.0.0.1:8081");
  EXPECT_FALSE(s.ui.start_paused);
  EXPECT_EQ(s.ui.speed, 0.0);
  EXPECT_THROW(scenario::parse_scenario("ui: {listen: 8080, start: later}\n", "t.yaml", "."), scenario::LoadError);
  EXPECT_THROW(scenario::parse_scenario("ui: {listen: 8080, speed: -1}\n", "t.yaml", "."), scenario::LoadError);
  EXPECT_THROW(scenario::parse_scenario("ui: {port: 8080}\n", "t.yaml", "."), scenario::LoadError);
}

TEST(UiOptions, RealTimeClockCannotBeControlled) {
  auto s = scenario::parse_scenario(vtest::kMachine + "clock: {mode: realtime}\n", "t.yaml", ".");
  vtest::LivePlant p(s, vtest::test_environment());
  const auto c = vtest::LivePlant::json_of(p.http().Get("/api/clock"));
  EXPECT_EQ(c["mode"], "realtime");
  EXPECT_EQ(c["paused"], false);
  const auto r = p.post("/api/clock", {{"action", "pause"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 409);
  // The small test product: a generic profile, its node live.
  const auto n = vtest::LivePlant::json_of(p.http().Get("/api/nodes/ax"));
  EXPECT_EQ(n["device"]["profile"], "generic");
  EXPECT_EQ(n["node_id"], 5);
}

}  // namespace
