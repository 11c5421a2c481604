// A component parameter: name, SI unit, default and the physically meaningful range. The same
// table drives validation of descriptions, run-time changes (fault injection) and the docs.
#pragma once

#include <string>
#include <string_view>

namespace plant {

struct ParameterSpec {
  std::string_view name;
  std::string_view unit;  ///< SI unit ("Pa", "m^3/s", "1" for dimensionless)
  double default_value;
  double min;
  double max;
  bool min_exclusive;  ///< true: value must be > min (areas, masses); false: >= min
  std::string_view description;
};

/// Empty when `value` is allowed, otherwise the reason ("must be > 0").
std::string check_range(const ParameterSpec& spec, double value);

}  // namespace plant
