// What the scenario engine needs from a plant: one Steppable with named ports and run-time
// parameters. plant_adapter.h puts plant::Plant behind it; tests use small plants of their own.
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/ports.h"
#include "sim/scheduler.h"

namespace scenario {

class PlantModel : public sim::Steppable {
 public:
  /// Ports named "<component>.<signal>"; value pointers stay valid for the plant's life.
  virtual const sim::PortList& ports() const = 0;
  /// Changes "<component>.<parameter>" between steps; returns an error message, empty on success.
  virtual std::string set_parameter(std::string_view name, double value) = 0;
  virtual std::optional<double> parameter(std::string_view name) const = 0;
  /// The names parameter() and set_parameter() know (for catalogues such as the control plane's).
  virtual std::vector<std::string> parameter_names() const { return {}; }
};

/// Builds a plant from a scenario's `plant:` section. Throws LoadError (`file:line:col: reason`).
using PlantFactory = std::function<std::unique_ptr<PlantModel>(const YAML::Node& section, const std::string& file)>;

}  // namespace scenario
