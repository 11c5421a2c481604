// sim::enter_realtime in a child process (a thread's policy and the locked memory must not leak
// into the other tests): SCHED_FIFO where permitted, and the message naming what is needed where not.
#include "sim/realtime_setup.h"

#include <gtest/gtest.h>
#include <pthread.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>

namespace {

struct ChildResult {
  std::string message;
  int policy = -1;
  int priority = -1;
  bool fifo = false;
};

// Runs enter_realtime() in a forked child after `prepare`, and reports what it did.
template <class Prepare>
ChildResult in_child(Prepare prepare) {
  int fds[2];
  EXPECT_EQ(pipe(fds), 0);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    prepare();
    const auto r = sim::enter_realtime();
    int policy = -1;
    sched_param param{};
    pthread_getschedparam(pthread_self(), &policy, &param);
    const std::string text = std::to_string(policy) + " " + std::to_string(param.sched_priority) + " " +
                             (r.fifo ? "1" : "0") + "\n" + r.message;
    if (write(fds[1], text.data(), text.size()) < 0) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  std::string out;
  char buf[512];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  ChildResult r;
  const auto nl = out.find('\n');
  if (nl == std::string::npos) return r;
  r.message = out.substr(nl + 1);
  int fifo = 0;
  std::sscanf(out.c_str(), "%d %d %d", &r.policy, &r.priority, &fifo);
  r.fifo = fifo == 1;
  return r;
}

}  // namespace

TEST(RealtimeSetup, FifoWherePermittedAndTheResultSaysSo) {
  const auto r = in_child([] {});
  if (r.fifo) {
    EXPECT_EQ(r.policy, SCHED_FIFO);
    EXPECT_EQ(r.priority, sim::kRealtimePriority);
    EXPECT_NE(r.message.find("SCHED_FIFO at priority 49"), std::string::npos) << r.message;
  } else {
    EXPECT_EQ(r.policy, SCHED_OTHER);
    EXPECT_NE(r.message.find("running with normal scheduling"), std::string::npos) << r.message;
  }
}

TEST(RealtimeSetup, RefusedItNamesTheCapabilityAndTheLimitsAndRunsOn) {
  // Without CAP_SYS_NICE and with RLIMIT_RTPRIO 0, SCHED_FIFO is EPERM; without CAP_IPC_LOCK and
  // with a finite RLIMIT_MEMLOCK nothing is locked. As root, drop to nobody (and its capabilities).
  const auto r = in_child([] {
    const rlimit zero{0, 0}, small{64 * 1024, 64 * 1024};
    setrlimit(RLIMIT_RTPRIO, &zero);
    setrlimit(RLIMIT_MEMLOCK, &small);
    if (geteuid() == 0) {
      if (setgid(65534) != 0 || setuid(65534) != 0) _exit(2);
    }
  });
  EXPECT_FALSE(r.fifo);
  EXPECT_EQ(r.policy, SCHED_OTHER);
  for (const char* needed : {"refused (EPERM)", "CAP_SYS_NICE", "RLIMIT_RTPRIO of at least 49", "ulimit -r",
                             "running with normal scheduling", "CAP_IPC_LOCK", "ulimit -l unlimited"}) {
    EXPECT_NE(r.message.find(needed), std::string::npos) << needed << " in:\n" << r.message;
  }
}
