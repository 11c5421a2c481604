// Process exit codes of the vplant command line, shared by every subcommand.
#pragma once

namespace vplant {

inline constexpr int kExitOk = 0;
inline constexpr int kExitAssertionFailed = 1;  ///< a scenario assertion did not hold
inline constexpr int kExitBadInput = 2;         ///< bad file, option, missing interface, ...

}  // namespace vplant
