#include "tools/vplant/case_pool.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>

namespace vplant {

namespace {

using Clock = std::chrono::steady_clock;

struct Child {
  std::size_t job = 0;
  Clock::time_point start, term_sent;
  bool timed_out = false, stopped = false, term = false, killed = false;
};

/// fork + exec with the output in `job.output` and stdin from /dev/null; -1 when fork failed.
pid_t spawn(const PoolJob& job, const sigset_t& child_mask) {
  std::vector<char*> argv;
  for (const auto& a : job.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid != 0) {
    if (pid > 0) ::setpgid(pid, pid);  // also in the child: whichever runs first
    return pid;
  }
  ::setpgid(0, 0);
  ::sigprocmask(SIG_SETMASK, &child_mask, nullptr);
  const int out = ::open(job.output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (out < 0 || in < 0 || ::dup2(out, 1) < 0 || ::dup2(out, 2) < 0 || ::dup2(in, 0) < 0) ::_exit(127);
  ::execv(argv[0], argv.data());
  const char* why = std::strerror(errno);
  (void)!::write(2, "vplant test: cannot run ", 24);
  (void)!::write(2, argv[0], std::strlen(argv[0]));
  (void)!::write(2, ": ", 2);
  (void)!::write(2, why, std::strlen(why));
  (void)!::write(2, "\n", 1);
  ::_exit(127);
}

}  // namespace

int run_pool(const std::vector<PoolJob>& jobs, const PoolOptions& options,
             const std::function<void(std::size_t, const PoolResult&)>& done) {
  // SIGCHLD, SIGINT and SIGTERM are taken with sigtimedwait: the loop sleeps until a child ends,
  // a stop is asked for, or the next deadline, and no handler runs behind its back.
  sigset_t wait_set, old_mask;
  sigemptyset(&wait_set);
  sigaddset(&wait_set, SIGCHLD);
  sigaddset(&wait_set, SIGINT);
  sigaddset(&wait_set, SIGTERM);
  ::sigprocmask(SIG_BLOCK, &wait_set, &old_mask);

  std::map<pid_t, Child> running;
  std::size_t next = 0;
  int stop_signal = 0;
  for (;;) {
    while (!stop_signal && running.size() < std::max<std::size_t>(options.jobs, 1) && next < jobs.size()) {
      Child c;
      c.job = next++;
      c.start = Clock::now();
      const pid_t pid = spawn(jobs[c.job], old_mask);
      if (pid < 0) {
        done(c.job, PoolResult{PoolResult::End::NotStarted, errno, 0});
        continue;
      }
      running.emplace(pid, c);
    }
    int status = 0;
    bool reaped = false;
    for (pid_t pid; !running.empty() && (pid = ::waitpid(-1, &status, WNOHANG)) > 0;) {
      reaped = true;
      const auto it = running.find(pid);
      if (it == running.end()) continue;
      const Child& c = it->second;
      PoolResult r;
      r.wall_s = std::chrono::duration<double>(Clock::now() - c.start).count();
      if (c.timed_out) r.end = PoolResult::End::TimedOut;
      else if (c.stopped) r.end = PoolResult::End::Stopped;
      else if (WIFSIGNALED(status)) r.end = PoolResult::End::Signalled;
      else r.end = PoolResult::End::Exited;
      r.code = WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status);
      const std::size_t job = c.job;
      running.erase(it);
      done(job, r);
    }
    if (running.empty() && (stop_signal || next >= jobs.size())) break;
    if (reaped) continue;  // start the next ones before waiting again

    const auto now = Clock::now();
    auto wake = now + std::chrono::milliseconds(500);
    for (auto& [pid, c] : running) {
      if (options.timeout.count() > 0 && !c.term) {
        const auto deadline = c.start + options.timeout;
        if (now >= deadline) {
          c.timed_out = c.term = true;
          c.term_sent = now;
          ::kill(-pid, SIGTERM);
        } else {
          wake = std::min(wake, deadline);
        }
      }
      if (c.term && !c.killed) {
        const auto deadline = c.term_sent + options.kill_grace;
        if (now >= deadline) {
          c.killed = true;
          ::kill(-pid, SIGKILL);
        } else {
          wake = std::min(wake, deadline);
        }
      }
    }
    const auto wait = std::chrono::duration_cast<std::chrono::nanoseconds>(std::max(wake - Clock::now(), Clock::duration(0)));
    timespec ts{static_cast<time_t>(wait.count() / 1000000000), static_cast<long>(wait.count() % 1000000000)};
    const int sig = ::sigtimedwait(&wait_set, nullptr, &ts);
    if ((sig == SIGINT || sig == SIGTERM) && !stop_signal) {
      stop_signal = sig;
      for (auto& [pid, c] : running) {
        c.stopped = c.term = true;
        c.term_sent = Clock::now();
        ::kill(-pid, SIGTERM);
      }
    }
  }
  for (; next < jobs.size(); ++next) done(next, PoolResult{});
  ::sigprocmask(SIG_SETMASK, &old_mask, nullptr);
  return stop_signal;
}

}  // namespace vplant
