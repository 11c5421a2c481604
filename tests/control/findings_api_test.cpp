// GET /api/findings: the verdict on the master while the run goes on (a frame sent through the
// control plane is the master's), page by page from ?since=N, bad `since` refused.
#include <gtest/gtest.h>

#include "tests/control/live_plant.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;

TEST(FindingsApi, FindingsOfTheMasterPageByPage) {
  LivePlant p(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment());
  p.run_ms(1000);  // the nodes boot
  json page = LivePlant::json_of(p.http().Get("/api/findings"));
  EXPECT_EQ(page["total"], 0) << page.dump();
  EXPECT_EQ(page["rules"]["sdo-no-answer"]["severity"], "error") << page.dump();

  // An NMT start to node 9 (not on the bus), then a write to the DSV's read-only 1000h.
  ASSERT_EQ(p.post("/api/frames", {{"bus", "main"}, {"id", "0x000"}, {"data", "0109"}})->status, 200);
  ASSERT_EQ(p.post("/api/frames", {{"bus", "main"}, {"id", "0x602"}, {"data", "2300100001000000"}})->status, 200);
  p.run_ms(10);
  page = LivePlant::json_of(p.http().Get("/api/findings?since=0"));
  ASSERT_EQ(page["total"], 2) << page.dump();
  EXPECT_EQ(page["findings"][0]["rule"], "nmt-unknown-node");
  EXPECT_EQ(page["findings"][0]["node"], 9);
  EXPECT_EQ(page["findings"][1]["rule"], "sdo-abort");
  EXPECT_EQ(page["findings"][1]["frames"][0]["frame"], "602#2300100001000000");
  EXPECT_EQ(page["next"], 2);

  page = LivePlant::json_of(p.http().Get("/api/findings?since=1"));
  ASSERT_EQ(page["findings"].size(), 1u) << page.dump();
  EXPECT_EQ(page["findings"][0]["rule"], "sdo-abort");
  EXPECT_EQ(LivePlant::json_of(p.http().Get("/api/findings?since=2"))["findings"].size(), 0u);
  EXPECT_EQ(p.http().Get("/api/findings?since=-1")->status, 400);
  EXPECT_EQ(p.http().Get("/api/findings?since=x")->status, 400);
}

}  // namespace
