// The control plane's server threads (HTTP workers, the listener, the event hub) yield the CPU to
// the simulation: on a machine with few cores a busy server thread must not delay the scheduler's
// next real-time tick. Each lowers its own priority (nice +10 for this thread only, as Linux
// allows without privileges); where that fails the thread simply runs at normal priority.
#pragma once

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace control {

inline void lower_this_thread_priority() {
  thread_local bool done = false;
  if (done) return;
  done = true;
  (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::syscall(SYS_gettid)), 10);
}

}  // namespace control
