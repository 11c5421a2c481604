// GET /api/findings: the verdict on the master while the run goes on (a frame sent through the
// control plane is the master's), page by page from ?since=N, bad `since` refused; new findings
// on the stream as `findings` pages, from 0 again after a restart.
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

/// The `findings` pages in a stream's text, in order.
std::vector<json> findings_events(const std::string& stream) { return vtest::events_of(stream, "findings"); }

TEST(FindingsApi, TheStreamCarriesNewFindingsOnceEachAndStartsAgainAfterARestart) {
  LivePlant p(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment());
  vtest::StreamCapture stream(p.port(), "");
  p.run_ms(1000);
  ASSERT_TRUE(stream.wait_for("event: faults"));  // the hub has read the live tables once
  EXPECT_TRUE(findings_events(stream.text()).empty()) << "no finding yet";

  ASSERT_EQ(p.post("/api/frames", {{"bus", "main"}, {"id", "0x000"}, {"data", "0109"}})->status, 200);
  p.run_ms(10);
  ASSERT_TRUE(stream.wait_for("event: findings"));
  ASSERT_EQ(p.post("/api/frames", {{"bus", "main"}, {"id", "0x602"}, {"data", "2300100001000000"}})->status, 200);
  p.run_ms(10);
  ASSERT_TRUE(stream.wait_for("\"rule\": \"sdo-abort\""));
  auto pages = findings_events(stream.text());
  ASSERT_EQ(pages.size(), 2u) << stream.text();
  ASSERT_EQ(pages[0]["findings"].size(), 1u);
  EXPECT_EQ(pages[0]["findings"][0]["rule"], "nmt-unknown-node");
  EXPECT_EQ(pages[0]["next"], 1);
  ASSERT_EQ(pages[1]["findings"].size(), 1u) << "each finding once";
  EXPECT_EQ(pages[1]["findings"][0]["rule"], "sdo-abort");
  EXPECT_EQ(pages[1]["next"], 2);
  EXPECT_EQ(pages[1]["total"], 2);
  EXPECT_EQ(pages[1]["rules"]["sdo-abort"]["count"], 1);

  // A restarted run's findings start at 0 again.
  ASSERT_EQ(p.post("/api/restart", json::object())->status, 200);
  ASSERT_TRUE(stream.wait_for("event: restart"));
  p.run_ms(1000);
  ASSERT_EQ(p.post("/api/frames", {{"bus", "main"}, {"id", "0x000"}, {"data", "0109"}})->status, 200);
  p.run_ms(10);
  for (int i = 0; i < 150 && findings_events(stream.text()).size() < 3; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  pages = findings_events(stream.text());
  ASSERT_EQ(pages.size(), 3u) << stream.text();
  EXPECT_EQ(pages[2]["findings"][0]["rule"], "nmt-unknown-node");
  EXPECT_EQ(pages[2]["next"], 1);
}

}  // namespace
