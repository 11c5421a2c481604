#include "plant/parameter.h"

#include <fmt/format.h>

#include <cmath>

namespace plant {

std::string check_range(const ParameterSpec& spec, double value) {
  if (!std::isfinite(value)) return fmt::format("parameter '{}' must be a finite number", spec.name);
  if (spec.min_exclusive ? !(value > spec.min) : !(value >= spec.min))
    return fmt::format("parameter '{}' = {} out of range: must be {} {} {}", spec.name, value,
                       spec.min_exclusive ? ">" : ">=", spec.min, spec.unit);
  if (value > spec.max)
    return fmt::format("parameter '{}' = {} out of range: must be <= {} {}", spec.name, value, spec.max, spec.unit);
  return {};
}

}  // namespace plant
