#include "tools/vplant/stop_signals.h"

#include <atomic>
#include <csignal>

namespace vplant {

namespace {

std::atomic<StopRequest> g_request{nullptr};
volatile std::sig_atomic_t g_stop_requested = 0;

extern "C" void on_stop_signal(int sig) {
  const StopRequest request = g_request.load();
  if (!g_stop_requested && request && request()) {
    g_stop_requested = 1;
    return;
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void install_stop_signals(StopRequest request) {
  g_request.store(request);
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
}

}  // namespace vplant
