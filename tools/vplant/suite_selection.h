// Which cases `vplant test PATH...` runs: the scenario files under the paths, each file's cases
// (its matrix combinations, engine/loading/scenario_cases.h), then --filter and --shard.
//
// Scenario files: every `*.yaml` under a folder (recursively, hidden entries skipped) except
// `*.plant.yaml`, the plant descriptions the scenarios include (scenarios/plant/); a file named
// on the command line is a scenario whatever its name.
//
// --shard K/N: the cases, sorted by (file path, position in the file's matrix), are dealt
// round-robin: case i (from 0) belongs to shard i mod N + 1. The shards are disjoint, together
// the whole suite, and the same on every machine for the same files and --filter (which applies
// first), as Playwright's and Jest's `--shard=K/N` are.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace vplant {

struct SuiteCase {
  std::string file;   ///< the scenario file, as found
  std::string name;   ///< the case name (`<name>` or `<name>[key=value,...]`)
  std::string error;  ///< the file could not be read: `file:line:col: reason` (name = file)
};

struct Shard {
  std::size_t index = 1;  ///< K, 1-based
  std::size_t count = 1;  ///< N
};

/// "K/N" with 1 <= K <= N; nullopt when malformed.
std::optional<Shard> parse_shard(const std::string& text);

/// The scenario files under `paths`, sorted, each once. A path that does not exist is an error
/// (`problem` names it; the result is then empty).
std::vector<std::string> find_scenario_files(const std::vector<std::string>& paths, std::string& problem);

/// Every case of the files, in file order then matrix order. A file that cannot be read
/// becomes one case that carries its error.
std::vector<SuiteCase> expand_cases(const std::vector<std::string>& files);

/// The cases whose name matches `glob` (fnmatch; "" = all), then those of `shard`.
std::vector<SuiteCase> select_cases(const std::vector<SuiteCase>& cases, const std::string& glob, const Shard& shard);

}  // namespace vplant
