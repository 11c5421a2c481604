// The classroom's one HTTP server (`vplant classroom`, docs/classroom.md): seat K's whole
// single-plant API and page under /seats/K/, the trainer's overview at / with its endpoints
// under /api/seats, every request admitted by its token (control/classroom_access.h) after the
// Host/Origin checks every control plane makes.
#pragma once

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "control/classroom_access.h"
#include "control/classroom_seat.h"

namespace control {

class ClassroomServer {
 public:
  /// `seats[k - 1]` is seat k; not owned, they outlive the server.
  ClassroomServer(ClassroomAccess access, std::vector<ClassroomSeat*> seats);
  ~ClassroomServer();
  ClassroomServer(const ClassroomServer&) = delete;
  ClassroomServer& operator=(const ClassroomServer&) = delete;

  /// Binds address:port (0 = ephemeral) and tells every seat where it is served; returns an
  /// error message, empty on success. A non-loopback address without allow_remote is refused.
  std::string listen(const std::string& address, int port, bool allow_remote);
  int port() const;
  /// Starts answering; call once every seat has attached to its run (their routes are in).
  void start();
  void stop();

  /// The links to hand out, each with its token: [0] the trainer's overview, [k] seat k.
  std::vector<std::string> links() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace control
