// The cases of a scenario file: the scenario itself, or, when it has a `matrix:`, one scenario
// per combination of the matrix's values (a parameter sweep, docs/scenarios.md "matrix").
//
//   matrix:
//     plant.cyl.viscous_friction: [1000, 2000, 3000]   # a reference-plant parameter
//     clock.seed: [1, 2]                                # any key of the file, by its path
//
// A key is a dotted path into the file: mappings by key, lists by the `name:` of an item
// (`nodes.dsv.settings.control_mode`, `faults.cable-break.at`); `plant.COMPONENT.PARAMETER` sets a
// plant parameter. A combination is the file with those values written in at those places, so
// every check of the loader and the world applies to it and an error points at the matrix value.
// Cases are named `<name>[key=value,...]`, in the order of the keys; the first key varies slowest.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "engine/loading/scenario.h"

namespace scenario {

/// At most this many combinations per file (a matrix is a product: it grows fast).
inline constexpr std::size_t kMaxMatrixCases = 10000;

class ScenarioCases {
 public:
  /// Reads and checks the file and its matrix (keys, lists, the first combination in full);
  /// throws LoadError `file:line:col`.
  static ScenarioCases load_file(const std::string& path);
  /// `file` names the text in errors; relative input paths resolve against `dir`.
  static ScenarioCases parse(const std::string& text, const std::string& file, const std::string& dir);

  std::size_t size() const { return names_.size(); }
  bool is_matrix() const { return !axes_.empty(); }
  /// `<scenario name>` or `<scenario name>[key=value,...]`.
  const std::string& name(std::size_t i) const { return names_[i]; }
  std::optional<std::size_t> find(const std::string& name) const;

  /// The scenario of case `i` (its name is the case name, its file outputs made distinct per
  /// combination by output_path). Throws LoadError at the offending value.
  Scenario load(std::size_t i) const;

  /// An output file of case `i`: unchanged without a matrix, else with the combination's values
  /// before the extension (`out/ref.log` → `out/ref.clock.seed=2.log`), so the cases of one file
  /// never write the same file.
  std::string output_path(const std::string& path, std::size_t i) const;

 private:
  struct Axis {
    std::string key;
    SourceMark mark;
    std::vector<std::string> values;  ///< as written, for names
  };

  ScenarioCases(std::string text, std::string file, std::string dir);
  /// Which value of each axis case `i` takes.
  std::vector<std::size_t> choice(std::size_t i) const;

  std::string text_, file_, dir_;
  std::vector<Axis> axes_;
  std::vector<std::string> values_;  ///< `key=value,...` per case ("" without a matrix)
  std::vector<std::string> names_;
  std::optional<Scenario> first_;    ///< case 0, parsed while checking the file
};

}  // namespace scenario
