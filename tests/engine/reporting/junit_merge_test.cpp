// The merged JUnit of `vplant test`: every testsuite of every case's file carries over verbatim,
// the counts are summed, a case without a file of its own gets an error suite.
#include <gtest/gtest.h>

#include "engine/reporting/junit_merge.h"
#include "engine/reporting/junit_writer.h"
#include "tests/support/read_file.h"
#include "tests/support/temp_path.h"

using namespace scenario;

namespace {

std::string case_junit(const std::string& suite, bool fail) {
  Verdicts v;
  v.pass("boots", SourceMark{"a.yaml", 3, 5}, sim::Time{});
  if (fail) v.fail("moves <fast>", SourceMark{"a.yaml", 9, 7}, sim::Time{} + sim::milliseconds(1500), "> 0.1", "0.02");
  vtest::TempPath path("case", ".xml");
  EXPECT_EQ(write_junit(path.str(), suite, v, 0.25, 2.0), "");
  return vtest::read_file(path.str());
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(JunitMerge, EveryTestsuiteOfEveryCaseCarriesOverWithTheCountsSummed) {
  const std::string a = case_junit("a[x=1]", false), b = case_junit("b", true);
  const auto sa = junit_testsuites(a), sb = junit_testsuites(b);
  ASSERT_EQ(sa.size(), 1u);
  ASSERT_EQ(sb.size(), 1u);
  EXPECT_EQ(sa[0].rfind("<testsuite name=\"a[x=1]\"", 0), 0u);
  EXPECT_EQ(sb[0].substr(sb[0].size() - 12), "</testsuite>");

  std::vector<std::string> suites = sa;
  suites.insert(suites.end(), sb.begin(), sb.end());
  suites.push_back(junit_error_suite("c", "TIMEOUT: stopped", "out <put> & more", 3.5));
  vtest::TempPath merged("merged", ".xml");
  ASSERT_EQ(write_merged_junit(merged.str(), suites), "");
  const std::string xml = vtest::read_file(merged.str());
  EXPECT_NE(xml.find("<testsuites tests=\"4\" failures=\"1\" errors=\"1\" time=\"4.000\">"), std::string::npos) << xml;
  EXPECT_NE(xml.find(sa[0]), std::string::npos);
  EXPECT_NE(xml.find(sb[0]), std::string::npos);
  EXPECT_EQ(count(xml, "<testsuite "), 3);
  EXPECT_EQ(count(xml, "<testcase "), 4);
  // The failure keeps its file:line:col; the error suite escapes what it quotes.
  EXPECT_NE(xml.find(">a.yaml:9:7: at t=1.500000 s: expected &gt; 0.1, actual 0.02</failure>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<error message=\"TIMEOUT: stopped\">out &lt;put&gt; &amp; more</error>"), std::string::npos) << xml;
  // And it reads back as the same suites.
  EXPECT_EQ(junit_testsuites(xml).size(), 3u);
}

TEST(JunitMerge, ADocumentWithoutSuitesGivesNoneAndAnUnwritablePathIsAnError) {
  EXPECT_TRUE(junit_testsuites("").empty());
  EXPECT_TRUE(junit_testsuites("<testsuites></testsuites>").empty());
  EXPECT_TRUE(junit_testsuites("<testsuite name=\"cut\" tests=\"1\">").empty());
  EXPECT_EQ(junit_testsuites("<testsuites><testsuite name=\"e\"/></testsuites>").at(0), "<testsuite name=\"e\"/>");
  EXPECT_NE(write_merged_junit("/dev/full", {"<testsuite name=\"a\"/>"}), "");
  EXPECT_NE(write_merged_junit("/nonexistent/dir/x.xml", {}), "");
}
