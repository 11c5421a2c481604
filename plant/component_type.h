// What a kind of component offers, known without building one: its parameters, the connectors
// a circuit can attach to it (fluid ports, shaft couplings) and its signal ports for devices.
// The description validator, the YAML parser and docs/plant.md all read these tables.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "plant/parameter.h"
#include "sim/ports.h"

namespace plant {

class Component;

/// What a connection joins: fluid ports share one pressure node; rotational connectors share one
/// rigid shaft (exactly one connector of the group owns the body, the others apply torque to it).
enum class Domain { Fluid, Rotational };

struct ConnectorSpec {
  std::string_view name;
  Domain domain;
  bool owns_body;  ///< rotational only: this connector is the rigid body the others act on
  std::string_view description;
};

struct SignalSpec {
  std::string_view name;
  sim::PortDirection direction;
  std::string_view unit;
  std::string_view description;
  sim::DisplayUnit display{};  ///< how an engineer reads it (the port's display unit)
};

struct ComponentType {
  std::string_view name;
  std::string_view description;
  std::span<const ParameterSpec> parameters;
  std::span<const ConnectorSpec> connectors;
  std::span<const SignalSpec> signals;
  /// Checks that involve several parameters (rod < bore, ...); empty string when consistent.
  std::string (*check)(std::span<const double> values);
  std::unique_ptr<Component> (*create)(std::string name, std::vector<double> values);

  int parameter_index(std::string_view parameter) const;  ///< -1 when unknown
  int connector_index(std::string_view connector) const;  ///< -1 when unknown
  std::vector<double> default_values() const;
};

/// Every component type the plant knows, in documentation order.
std::span<const ComponentType* const> component_types();
const ComponentType* find_component_type(std::string_view name);

}  // namespace plant
