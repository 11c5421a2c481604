// SIGINT/SIGTERM for `vplant run` and `vplant node`: installed before loading, so a signal in any
// phase ends the process; while a loop runs, the first one asks it to stop. Each case runs in a
// child process (the handlers are process-wide).
#include "tools/vplant/stop_signals.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>

namespace {

std::atomic<int> g_requests{0};
bool no_loop_runs() { return false; }
bool loop_runs() {
  ++g_requests;
  return true;
}

// Runs `body` in a child and returns its wait status.
template <typename F>
int in_child(F body) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    body();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace

TEST(StopSignals, WhileLoadingASignalEndsTheProcess) {
  for (int sig : {SIGINT, SIGTERM}) {
    const int status = in_child([sig] {
      vplant::install_stop_signals(no_loop_runs);
      std::raise(sig);
      ::_exit(3);  // not reached: the signal's default action ended the process
    });
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), sig);
  }
}

TEST(StopSignals, WhileALoopRunsTheFirstSignalStopsItAndASecondEndsTheProcess) {
  const int status = in_child([] {
    vplant::install_stop_signals(loop_runs);
    std::raise(SIGTERM);
    if (g_requests.load() != 1) ::_exit(4);
    std::raise(SIGINT);
    ::_exit(5);  // not reached
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGINT);
}
