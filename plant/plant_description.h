// A plant as data: which components (type, name, parameter values) and how their connectors are
// joined. Built in code (reference_plant.h) or read from a scenario's `plant:` section
// (plant_yaml.h); every piece remembers where it was written so errors point at it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "plant/diagnostic.h"

namespace plant {

struct ParameterSetting {
  std::string name;
  double value = 0.0;
  SourceMark name_mark;
  SourceMark value_mark;
};

struct ComponentDescription {
  std::string type;
  std::string name;
  std::vector<ParameterSetting> parameters;  ///< overrides of the type's defaults
  SourceMark mark;
  SourceMark type_mark;
  SourceMark name_mark;
};

/// "component.connector", e.g. "valve_cyl.A" or "motor.shaft".
struct PortReference {
  std::string component;
  std::string connector;
  SourceMark mark;

  std::string to_string() const { return component + "." + connector; }
};

/// One node of the circuit: fluid ports that share a pressure, or rotational connectors coupled
/// rigidly to one shaft.
struct ConnectionDescription {
  std::string name;
  std::vector<PortReference> ports;
  double initial_pressure = 0.0;  ///< Pa, fluid nodes without a tank
  SourceMark mark;
};

struct SolverSettings {
  double max_step = 1e-3;  ///< s; each tick is split into equal physics steps no longer than this
  SourceMark mark;
};

struct PlantDescription {
  std::vector<ComponentDescription> components;
  std::vector<ConnectionDescription> connections;
  SolverSettings solver;

  /// Adds a component; parameters not given keep the type's defaults.
  ComponentDescription& add(std::string type, std::string name,
                            std::vector<std::pair<std::string, double>> parameters = {});
  /// Adds a connection from "component.connector" strings.
  ConnectionDescription& connect(std::string name, const std::vector<std::string>& ports,
                                 double initial_pressure = 0.0);
};

/// Parses "component.connector" (split at the first '.').
PortReference parse_port_reference(const std::string& text, SourceMark mark = {});

/// Throws DescriptionError at the first problem: unknown type or parameter, value out of range,
/// inconsistent parameters, duplicate or malformed names, no or several fluids, connections to
/// missing components or connectors, a connector used twice or never, mixed domains, a node with
/// two tanks, a shaft coupling without exactly one body.
void validate(const PlantDescription& description);

/// The full parameter vector of a component: the type's defaults with the overrides applied.
/// Assumes the description is valid.
std::vector<double> resolved_parameters(const ComponentDescription& component);

/// Same components, parameters, connections and settings (source marks ignored; parameter
/// settings compared after resolution, so an explicit default equals an omitted one).
bool equivalent(const PlantDescription& a, const PlantDescription& b);

}  // namespace plant
