// The child processes of `vplant test`: exit codes, a crash and a hang are each reported as what
// they are, the others run to their end, and no more than `jobs` run at once.
#include <gtest/gtest.h>

#include <csignal>
#include <map>

#include "tests/support/read_file.h"
#include "tests/support/temp_path.h"
#include "tools/vplant/case_pool.h"

using vplant::PoolJob;
using vplant::PoolResult;

namespace {

PoolJob shell(const std::string& script, const std::string& output) { return PoolJob{{"/bin/sh", "-c", script}, output}; }

}  // namespace

TEST(CasePool, ACrashAndAHangAreReportedAndTheOthersFinish) {
  vtest::TempPath dir("pool");
  std::filesystem::create_directories(dir.str());
  const std::string d = dir.str() + "/";
  const std::vector<PoolJob> jobs = {
      shell("echo passed; exit 0", d + "0.out"),
      shell("echo crashing; kill -SEGV $$", d + "1.out"),
      shell("echo hanging; exec sleep 100", d + "2.out"),
      shell("echo failed >&2; exit 1", d + "3.out"),
      shell("exit 3", d + "4.out"),
  };
  vplant::PoolOptions options;
  options.jobs = 2;
  options.timeout = std::chrono::milliseconds(1500);
  std::map<std::size_t, PoolResult> results;
  std::vector<std::size_t> order;
  const int stop = vplant::run_pool(jobs, options, [&](std::size_t i, const PoolResult& r) {
    results[i] = r;
    order.push_back(i);
  });
  EXPECT_EQ(stop, 0);
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(results[0].end, PoolResult::End::Exited);
  EXPECT_EQ(results[0].code, 0);
  EXPECT_EQ(results[1].end, PoolResult::End::Signalled);
  EXPECT_EQ(results[1].code, SIGSEGV);
  EXPECT_EQ(results[2].end, PoolResult::End::TimedOut);
  EXPECT_GE(results[2].wall_s, 1.4);
  EXPECT_LT(results[2].wall_s, 10.0);
  EXPECT_EQ(results[3].end, PoolResult::End::Exited);
  EXPECT_EQ(results[3].code, 1);
  EXPECT_EQ(results[4].code, 3);
  EXPECT_EQ(order.back(), 2u);  // the hang ends last: the others ran beside it
  // Each child's stdout and stderr went to its own file.
  EXPECT_EQ(vtest::read_file(d + "0.out"), "passed\n");
  EXPECT_EQ(vtest::read_file(d + "2.out"), "hanging\n");
  EXPECT_EQ(vtest::read_file(d + "3.out"), "failed\n");
}

TEST(CasePool, NoMoreThanJobsRunAtOnce) {
  vtest::TempPath dir("pool");
  std::filesystem::create_directories(dir.str());
  // Each job counts the others running: a file per running job in `dir`.
  std::vector<PoolJob> jobs;
  for (int i = 0; i < 6; ++i)
    jobs.push_back(shell("cd '" + dir.str() + "' && touch run." + std::to_string(i) +
                             " && sleep 0.2 && ls run.* | wc -l > seen." + std::to_string(i) + " && rm run." + std::to_string(i),
                         "/dev/null"));
  vplant::PoolOptions options;
  options.jobs = 2;
  std::size_t done = 0;
  vplant::run_pool(jobs, options, [&](std::size_t, const PoolResult& r) {
    EXPECT_EQ(r.end, PoolResult::End::Exited);
    ++done;
  });
  EXPECT_EQ(done, 6u);
  for (int i = 0; i < 6; ++i) {
    const int seen = std::atoi(vtest::read_file(dir.str() + "/seen." + std::to_string(i)).c_str());
    EXPECT_GE(seen, 1);
    EXPECT_LE(seen, 2);
  }
}

TEST(CasePool, AProgramThatCannotStartExits127WithTheReason) {
  vtest::TempPath out("pool", ".out");
  PoolResult result;
  vplant::run_pool({PoolJob{{"/nonexistent/vplant", "run"}, out.str()}}, vplant::PoolOptions{},
                   [&](std::size_t, const PoolResult& r) { result = r; });
  EXPECT_EQ(result.end, PoolResult::End::Exited);
  EXPECT_EQ(result.code, 127);
  EXPECT_NE(vtest::read_file(out.str()).find("cannot run /nonexistent/vplant: No such file or directory"), std::string::npos);
}
