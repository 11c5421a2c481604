// The live control plane (issue 11): an HTTP API and server-sent-event stream beside a running
// scenario (docs/api.md). It is the run's RunExtension; the HTTP server runs on its own threads
// and reaches the simulation only through the SimBridge (commands queued between ticks,
// published snapshots). `vplant run --ui [ADDR:]PORT` creates one.
#pragma once

#include <atomic>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "control/exercise_host.h"
#include "control/sim_bridge.h"
#include "engine/running/run_extension.h"

namespace control {

struct UiOptions {
  std::string address = "127.0.0.1";
  int port = 0;               ///< 0 = an ephemeral port (tests)
  bool allow_remote = false;  ///< a non-loopback address needs it
  ClockOptions clock;
  std::size_t max_streams = 4;
  std::FILE* out = stderr;    ///< the URL line and warnings; nullptr = silent
  std::string exercises_dir;  ///< exercise files (docs/exercises.md); "" = none
  std::string exercise;       ///< selected at the start ("" = none)
};

namespace http {
struct Request;
struct Response;
}  // namespace http

/// Parses "[ADDR:]PORT" into `options`; returns an error message, empty on success.
std::string parse_ui_address(std::string_view text, UiOptions& options);
bool is_loopback(const std::string& address);

class ControlPlane final : public scenario::RunExtension {
 public:
  explicit ControlPlane(UiOptions options);
  ~ControlPlane() override;
  ControlPlane(const ControlPlane&) = delete;
  ControlPlane& operator=(const ControlPlane&) = delete;

  /// Binds the listening socket (before the run, so a taken port fails early); returns an error
  /// message, empty on success. A non-loopback address without allow_remote is refused.
  std::string bind();
  int port() const { return port_; }
  std::string url() const;

  // scenario::RunExtension: attach starts serving (and prints the URL); detach stops the
  // simulation side (the server answers 503 "the run has ended" until destroyed).
  void attach(const scenario::RunContext& context) override;
  bool before_tick(bool end_reached) override {
    exercises_.check();
    return bridge_.before_tick(end_reached);
  }
  void detach() override;
  bool wants_restart() override { return bridge_.wants_restart(); }

  SimBridge& bridge() { return bridge_; }
  /// Its routes are in place (set at the end of the first attach; the bridge is attached before
  /// the routes are added): a host serves its requests only from then on.
  bool routed() const { return routed_.load(); }

  // Hosted (a classroom seat, control/classroom_server.h): no server of its own; the host's
  // server, listening at `address:port`, hands it the requests for its prefix, the prefix
  // stripped. Call host_at instead of bind, before the run.
  void host_at(const std::string& address, int port);
  /// The Host/Origin/Sec-Fetch-Site checks (an http::Admission): status 0 = admitted.
  http::Response admit(const http::Request& request) const;
  /// Answers a request (the API, else the page's files).
  void handle(http::Request& request, http::Response& response);

 private:
  struct Server;
  UiOptions options_;
  int port_ = 0;
  SimBridge bridge_;
  ExerciseHost exercises_;
  std::unique_ptr<Server> server_;
  std::atomic<bool> routed_{false};
};

}  // namespace control
