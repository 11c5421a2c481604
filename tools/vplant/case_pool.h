// Runs commands as child processes, at most `jobs` at a time, each in its own process group
// with its output (stdout and stderr) in a file, so a case that crashes, hangs or floods its
// output cannot take the others or `vplant test` down. A child past its timeout gets SIGTERM
// (vplant run then stops and reports), and SIGKILL 2 s later. SIGINT/SIGTERM to the pool stop
// it: the children get SIGTERM, no new one starts.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace vplant {

struct PoolJob {
  std::vector<std::string> argv;  ///< argv[0] is the program's path
  std::string output;             ///< file for the child's stdout and stderr
};

struct PoolResult {
  enum class End { Exited, Signalled, TimedOut, Stopped, NotStarted } end = End::NotStarted;
  int code = 0;        ///< Exited: the exit code; Signalled: the signal
  double wall_s = 0;   ///< from start to end
};

struct PoolOptions {
  std::size_t jobs = 1;
  std::chrono::milliseconds timeout{0};  ///< per job; 0 = none
  std::chrono::milliseconds kill_grace{2000};
};

/// Runs every job; `done(i, result)` is called as each one ends (in the order they end).
/// Returns the signal that stopped the pool, 0 when every job ran.
int run_pool(const std::vector<PoolJob>& jobs, const PoolOptions& options,
             const std::function<void(std::size_t, const PoolResult&)>& done);

}  // namespace vplant
