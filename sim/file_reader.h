// Reading an input file (EDS, scenario, plant description, parameter store) safely: only a
// regular file is read, never more than a bounded size, and opening never blocks. A FIFO would
// block open() until a writer appears, /dev/zero never ends and a directory reads as nothing, so
// each is rejected with a reason instead of hanging, growing or being taken for an empty file.
#pragma once

#include <cstddef>
#include <string>

namespace sim {

/// The largest input file vplant reads (docs/runtime.md, "Input files"); real EDS files are at
/// most a few hundred kilobytes and scenario files a few.
inline constexpr std::size_t kMaxInputFileBytes = 16u << 20;

enum class ReadStatus { Ok, Missing, Failed };

/// Reads the whole file at `path` into `text`. Missing: the path does not exist (callers decide
/// whether that is an error). Failed: `reason` says why, without the path (e.g. "not a regular
/// file (a FIFO)", "larger than 16777216 bytes"); callers print it as "file: reason".
ReadStatus read_input_file(const std::string& path, std::string& text, std::string& reason,
                           std::size_t max_bytes = kMaxInputFileBytes);

}  // namespace sim
