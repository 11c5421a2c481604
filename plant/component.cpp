#include "plant/component.h"

#include <fmt/format.h>

#include <cmath>

namespace plant {

Component::Component(const ComponentType& type, std::string name, std::vector<double> values)
    : type_(type),
      name_(std::move(name)),
      values_(std::move(values)),
      signals_(type.signals.size(), 0.0),
      targets_(type.connectors.size(), -1) {}

Status Component::set_parameter(std::string_view parameter, double value) {
  const int index = type_.parameter_index(parameter);
  if (index < 0) return Status::failure(fmt::format("{} '{}' has no parameter '{}'", type_.name, name_, parameter));
  if (auto why = check_range(type_.parameters[static_cast<std::size_t>(index)], value); !why.empty())
    return Status::failure(fmt::format("{}: {}", name_, why));
  std::vector<double> candidate = values_;
  candidate[static_cast<std::size_t>(index)] = value;
  if (type_.check != nullptr) {
    if (auto why = type_.check(candidate); !why.empty()) return Status::failure(fmt::format("{}: {}", name_, why));
  }
  values_ = std::move(candidate);
  parameters_changed();
  return Status::success();
}

}  // namespace plant
