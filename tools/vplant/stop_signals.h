// SIGINT and SIGTERM for `vplant run` and `vplant node`, installed before anything is loaded.
// While a simulation loop runs, the first signal asks it to stop (the run then reports and writes
// its outputs as usual); in every other phase (loading, building, writing outputs) and on a second
// signal, the signal's default action ends the process at once.
#pragma once

namespace vplant {

/// Asks the running loop to stop; returns false when no loop runs. Called in a signal handler:
/// it may only touch atomics.
using StopRequest = bool (*)();

void install_stop_signals(StopRequest request);

}  // namespace vplant
