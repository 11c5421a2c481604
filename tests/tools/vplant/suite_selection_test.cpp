// Which cases `vplant test` runs: scenario files under folders, --filter, and --shard K/N
// partitions that are disjoint and whole for any N.
#include <gtest/gtest.h>

#include <set>

#include "tools/vplant/suite_selection.h"

using vplant::Shard;
using vplant::SuiteCase;

TEST(SuiteSelection, ShardsAreDisjointAndTogetherTheSuiteForAnyCount) {
  std::vector<SuiteCase> cases;
  for (int i = 0; i < 23; ++i) cases.push_back({"f.yaml", "case-" + std::to_string(i), {}});
  for (std::size_t n = 1; n <= 30; ++n) {
    std::multiset<std::string> seen;
    std::size_t smallest = SIZE_MAX, largest = 0;
    for (std::size_t k = 1; k <= n; ++k) {
      const auto shard = vplant::select_cases(cases, "", Shard{k, n});
      smallest = std::min(smallest, shard.size());
      largest = std::max(largest, shard.size());
      for (const auto& c : shard) seen.insert(c.name);
    }
    EXPECT_EQ(seen.size(), cases.size()) << n;
    EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), cases.size()) << n;
    EXPECT_LE(largest - smallest, 1u) << n;  // round-robin: balanced
  }
}

TEST(SuiteSelection, TheFilterAppliesBeforeTheShard) {
  const std::vector<SuiteCase> cases = {{"a", "fault-a", {}}, {"b", "ok-b", {}}, {"c", "fault-c", {}}, {"d", "fault-d", {}}};
  const auto first = vplant::select_cases(cases, "fault-*", Shard{1, 2});
  const auto second = vplant::select_cases(cases, "fault-*", Shard{2, 2});
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].name, "fault-a");
  EXPECT_EQ(first[1].name, "fault-d");
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].name, "fault-c");
}

TEST(SuiteSelection, ParsesShards) {
  EXPECT_EQ(vplant::parse_shard("2/3")->index, 2u);
  EXPECT_EQ(vplant::parse_shard("2/3")->count, 3u);
  for (const char* bad : {"0/3", "4/3", "1/0", "3", "a/b", "1/", "/2", "-1/2"}) EXPECT_FALSE(vplant::parse_shard(bad)) << bad;
}

TEST(SuiteSelection, FindsScenarioFilesButNotPlantFiles) {
  std::string problem;
  const auto files = vplant::find_scenario_files({VPLANT_SOURCE_DIR "/scenarios"}, problem);
  EXPECT_EQ(problem, "");
  ASSERT_FALSE(files.empty());
  EXPECT_EQ(files.front(), VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml");
  for (const auto& f : files) EXPECT_EQ(f.find(".plant.yaml"), std::string::npos) << f;
  EXPECT_TRUE(std::is_sorted(files.begin(), files.end()));
  EXPECT_TRUE(vplant::find_scenario_files({VPLANT_SOURCE_DIR "/no-such-folder"}, problem).empty());
  EXPECT_EQ(problem, VPLANT_SOURCE_DIR "/no-such-folder: no such file or folder");
}
