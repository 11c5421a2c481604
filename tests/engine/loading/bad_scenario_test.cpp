// Every malformed scenario under tests/data/scenarios/bad/ is rejected with `file:line:col:
// reason`. Each file states what it expects on its first line: `# error: LINE:COL: text`.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "tests/engine/test_world.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"

namespace {

struct Expected {
  int line = -1, column = -1;
  std::string text;
};

Expected expected_error(const std::string& path) {
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  Expected e;
  if (std::sscanf(first.c_str(), "# error: %d:%d:", &e.line, &e.column) == 2) {
    const auto colon = first.find(':', first.find(':', first.find(':') + 1) + 1);
    e.text = first.substr(colon + 2);
  }
  return e;
}

std::string build_error(const std::string& path) {
  std::FILE* out = std::tmpfile();
  try {
    const auto s = scenario::load_scenario_file(path);
    scenario::RunOptions o;
    o.out = out;
    scenario::Runner runner(s, vtest::test_environment(), o);
  } catch (const scenario::LoadError& e) {
    std::fclose(out);
    return e.what();
  }
  std::fclose(out);
  return "accepted";
}

}  // namespace

TEST(BadScenario, EachFileIsRejectedAtItsLineWithItsReason) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(VPLANT_BAD_SCENARIOS)) {
    const std::string path = entry.path().string();
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const auto e = expected_error(path);
    ASSERT_GE(e.line, 0) << path << ": first line must be '# error: LINE:COL: text'";
    const std::string prefix = e.line == 0 ? path + ": " : path + ":" + std::to_string(e.line) + ":" + std::to_string(e.column) + ": ";
    const auto got = build_error(path);
    EXPECT_EQ(got.rfind(prefix, 0), 0u) << "expected at " << prefix << "\n got: " << got;
    EXPECT_NE(got.find(e.text), std::string::npos) << "expected '" << e.text << "'\n got: " << got;
  }
  EXPECT_GE(files, 20);
}

TEST(BadScenario, MissingFileIsReported) {
  EXPECT_EQ(build_error("/nonexistent/scenario.yaml"), "/nonexistent/scenario.yaml: cannot open the scenario file");
}
