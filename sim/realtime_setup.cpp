#include "sim/realtime_setup.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace sim {

namespace {

std::string limit_text(rlim_t v) { return v == RLIM_INFINITY ? "unlimited" : std::to_string(v); }


std::string set_fifo(int priority, bool& ok) {
  sched_param param{};
  param.sched_priority = priority;
  const int rc = ::pthread_setschedparam(::pthread_self(), SCHED_FIFO, &param);
  if (rc == 0) {
    ok = true;
    return "real time: the scheduler thread runs SCHED_FIFO at priority " + std::to_string(priority);
  }
  if (rc == EPERM) {
    rlimit rt{};
    ::getrlimit(RLIMIT_RTPRIO, &rt);
    return "real time: SCHED_FIFO priority " + std::to_string(priority) +
           " refused (EPERM): it needs CAP_SYS_NICE (e.g. `sudo setcap cap_sys_nice+ep vplant`) or an RLIMIT_RTPRIO of at "
           "least " + std::to_string(priority) + " (`ulimit -r`, /etc/security/limits.conf `rtprio`; now " +
           limit_text(rt.rlim_cur) + "); running with normal scheduling";
  }
  return std::string("real time: SCHED_FIFO refused (") + std::strerror(rc) + "); running with normal scheduling";
}

std::string lock_memory(bool& ok) {
  // With a finite RLIMIT_MEMLOCK and no CAP_IPC_LOCK, MCL_FUTURE would make every later
  // allocation beyond the limit fail: lock only when the limit cannot be hit.
  rlimit mem{};
  ::getrlimit(RLIMIT_MEMLOCK, &mem);
  const bool privileged = ::geteuid() == 0;
  if (!privileged && mem.rlim_cur != RLIM_INFINITY) {
    return "real time: memory not locked: mlockall needs CAP_IPC_LOCK or an unlimited RLIMIT_MEMLOCK (`ulimit -l "
           "unlimited`, limits.conf `memlock`; now " +
           std::to_string(mem.rlim_cur / 1024) + " KiB); page faults may delay ticks";
  }
  if (::mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
    ok = true;
    return "real time: memory locked (mlockall)";
  }
  const int e = errno;
  return std::string("real time: memory not locked: mlockall failed (") + std::strerror(e) +
         (e == EPERM || e == ENOMEM ? "; it needs CAP_IPC_LOCK or an unlimited RLIMIT_MEMLOCK, `ulimit -l unlimited`" : "") +
         "); page faults may delay ticks";
}

}  // namespace

RealtimeSetup enter_realtime(int priority) {
  RealtimeSetup r;
  r.message = set_fifo(priority, r.fifo) + "\n" + lock_memory(r.locked);
  return r;
}

}  // namespace sim
