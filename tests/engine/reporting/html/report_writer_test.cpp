// The HTML report: a run's case (summary, inlined data: assertions, plots, bounded trace, bus
// load, faults) and the index built from the cases/ folder (engine/reporting/html/).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/reporting/html/frame_capture.h"
#include "engine/reporting/html/report_writer.h"
#include "tests/engine/run_helper.h"
#include "tests/support/read_file.h"
#include "tests/support/temp_path.h"
#include "tests/engine/test_world.h"

namespace {

using nlohmann::json;
using vtest::read_file;

// SYNC every millisecond for 3 s: more frames than the report keeps.
const std::string kRun = vtest::kMachine + R"(
name: axis </script> case
clock: {duration: 3s}
outputs:
  sample_period: 10ms
  plots:
    - {title: Axis, y_label: "position [mm]", signals: [{signal: axis.position * 1000, label: plant}]}
faults:
  - {name: ax off the bus, at: 1s, for: 200ms, bus_off: ax}
script:
  - nmt: start
  - sync: 1ms
  - name: never reached
    expect: {signal: axis.position, above: 5, within: 500ms}
)";

// The JSON a page carries in <script type="application/json" id="ID">.
json inlined(const std::string& page, const std::string& id) {
  const std::string open = "<script type=\"application/json\" id=\"" + id + "\">";
  const auto begin = page.find(open);
  if (begin == std::string::npos) return nullptr;
  const auto from = begin + open.size();
  return json::parse(page.substr(from, page.find("</script>", from) - from));
}

TEST(ReportWriter, CaseIdKeepsSafeCharacters) {
  EXPECT_EQ(scenario::report::case_id("hlt-magnet_lost.v2"), "hlt-magnet_lost.v2");
  EXPECT_EQ(scenario::report::case_id("sweep[gain=2,seed=7]"), "sweep_gain_2_seed_7_");
  EXPECT_EQ(scenario::report::case_id("../.."), ".._..");
  EXPECT_EQ(scenario::report::case_id(".."), "_..");
  EXPECT_EQ(scenario::report::case_id(""), "case");
}

TEST(ReportWriter, RunWritesCaseWithFailureTimelineDataAndBoundedTrace) {
  const vtest::TempPath dir("vplant-report");
  scenario::RunOptions options;
  options.report_dir = dir.str();
  const auto r = vtest::run_text(kRun, options);
  ASSERT_EQ(r.rc, 1) << r.output;
  const std::string id = "axis___script__case";
  const auto case_dir = dir.str() + "/cases/" + id;

  const json summary = json::parse(read_file(case_dir + "/case.json"));
  EXPECT_EQ(summary["name"], "axis </script> case");
  EXPECT_EQ(summary["result"], "failed");
  EXPECT_EQ(summary["assertions"], 1);
  EXPECT_EQ(summary["failures"], 1);
  EXPECT_EQ(summary["faults"], 1);
  EXPECT_EQ(summary["first_failure"]["name"], "never reached");
  EXPECT_EQ(summary["first_failure"]["where"].get<std::string>().rfind("test.yaml:", 0), 0u);
  EXPECT_EQ(summary["page"], "cases/" + id + "/index.html");

  const std::string page = read_file(case_dir + "/index.html");
  // The name's "</script>" is escaped: the data element ends once, the script tag closes once.
  std::size_t closing = 0;
  for (auto p = page.find("</script>"); p != std::string::npos; p = page.find("</script>", p + 1)) ++closing;
  EXPECT_EQ(closing, 2u);
  EXPECT_NE(page.find("src=\"../../assets/report.js\""), std::string::npos);
  const json data = inlined(page, "case-data");
  ASSERT_TRUE(data.is_object()) << page.substr(0, 400);
  EXPECT_EQ(data["outcomes"].size(), 1u);
  EXPECT_FALSE(data["outcomes"][0]["passed"].get<bool>());
  EXPECT_NE(data["outcomes"][0]["expected"].get<std::string>().find("axis.position > 5"), std::string::npos);

  // The scenario's plot and the bus load plot over the recorded samples (every 10 ms).
  ASSERT_EQ(data["plots"].size(), 2u);
  EXPECT_EQ(data["plots"][0]["title"], "Axis");
  EXPECT_EQ(data["plots"][0]["labels"][0], "plant");
  EXPECT_EQ(data["plots"][1]["title"], "bus load");
  EXPECT_EQ(data["signals"]["names"][0], "axis.position * 1000");
  EXPECT_EQ(data["signals"]["t"].size(), 300u);
  EXPECT_EQ(data["signals"]["values"][0].size(), 300u);

  // Bounded trace: the first and the last FrameCapture::kHead/kTail of the ~3000 frames, decoded.
  using scenario::report::FrameCapture;
  const auto& rows = data["trace"]["rows"];
  EXPECT_GT(data["trace"]["seen"].get<std::uint64_t>(), FrameCapture::kHead + FrameCapture::kTail);
  ASSERT_EQ(rows.size(), FrameCapture::kHead + FrameCapture::kTail);
  EXPECT_EQ(data["trace"]["buses"][0], "main");
  EXPECT_LT(rows[0][0].get<std::int64_t>(), 10'000);
  EXPECT_GT(rows[rows.size() - 1][0].get<std::int64_t>(), 2'990'000);
  bool sync = false;
  for (const auto& row : rows) sync = sync || row[6] == "SYNC";
  EXPECT_TRUE(sync);

  ASSERT_EQ(data["buses"].size(), 1u);
  EXPECT_GT(data["buses"][0]["mean_load"].get<double>(), 0.0);
  EXPECT_EQ(data["buses"][0]["ids"][0]["id"], 0x80);  // SYNC occupies the bus most
  ASSERT_GE(data["events"].size(), 1u);
  EXPECT_EQ(data["events"][0]["kind"], "fault");
  EXPECT_NEAR(data["events"][0]["t"].get<double>(), 1.0, 1e-9);

  EXPECT_TRUE(std::filesystem::is_regular_file(dir.str() + "/assets/report.js"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.str() + "/assets/report.css"));
}

TEST(ReportWriter, IndexListsEveryCaseFolderAndMarksUnreadableOnes) {
  const vtest::TempPath dir("vplant-report-index");
  scenario::report::CaseRecord passed;
  passed.name = "b passes";
  passed.simulated_s = 2;
  passed.wall_s = 0.5;
  ASSERT_EQ(scenario::report::write_case(dir.str(), passed), "");
  scenario::report::CaseRecord failed = passed;
  failed.name = "a fails";
  failed.exit_code = 1;
  failed.outcomes.push_back({"holds", {"a.yaml", 3, 5}, false, sim::Time{sim::milliseconds(1500)}, "x > 1", "0"});
  ASSERT_EQ(scenario::report::write_case(dir.str(), failed), "");
  // A case whose process died before its summary, and one with a damaged summary.
  std::filesystem::create_directories(dir.str() + "/cases/crashed");
  std::filesystem::create_directories(dir.str() + "/cases/damaged");
  std::ofstream(dir.str() + "/cases/damaged/case.json") << "{\"name\": ";

  ASSERT_EQ(scenario::report::write_index(dir.str()), "");
  const json index = inlined(read_file(dir.str() + "/index.html"), "index-data");
  ASSERT_EQ(index["cases"].size(), 4u);
  EXPECT_EQ(index["cases"][0]["name"], "a fails");
  EXPECT_EQ(index["cases"][0]["result"], "failed");
  EXPECT_EQ(index["cases"][0]["first_failure"]["where"], "a.yaml:3:5");
  EXPECT_EQ(index["cases"][0]["page"], "cases/a_fails/index.html");
  EXPECT_EQ(index["cases"][1]["name"], "b passes");
  EXPECT_EQ(index["cases"][1]["result"], "passed");
  EXPECT_DOUBLE_EQ(index["cases"][1]["simulated_s"].get<double>(), 2.0);
  EXPECT_EQ(index["cases"][2]["id"], "crashed");
  EXPECT_EQ(index["cases"][2]["result"], "error");
  EXPECT_NE(index["cases"][2]["error"].get<std::string>().find("did not finish"), std::string::npos);
  EXPECT_EQ(index["cases"][3]["result"], "error");
  EXPECT_NE(index["cases"][3]["error"].get<std::string>().find("not a case summary"), std::string::npos);
}

TEST(ReportWriter, UnwritableFolderIsAnError) {
  const vtest::TempPath file("vplant-report-file");
  std::ofstream(file.str()) << "a file, not a folder";
  scenario::report::CaseRecord r;
  r.name = "x";
  EXPECT_NE(scenario::report::write_case(file.str(), r), "");
  EXPECT_NE(scenario::report::write_index(file.str()), "");
}

}  // namespace
