#include "plant/plant_description.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "plant/component_type.h"

namespace plant {
namespace {

[[noreturn]] void fail(const SourceMark& mark, std::string reason) {
  throw DescriptionError(Diagnostic{mark, std::move(reason)});
}

bool valid_name(const std::string& name) {
  if (name.empty()) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

}  // namespace

ComponentDescription& PlantDescription::add(std::string type, std::string name,
                                            std::vector<std::pair<std::string, double>> parameters) {
  ComponentDescription c;
  c.type = std::move(type);
  c.name = std::move(name);
  for (auto& [key, value] : parameters) c.parameters.push_back(ParameterSetting{std::move(key), value, {}, {}});
  components.push_back(std::move(c));
  return components.back();
}

ConnectionDescription& PlantDescription::connect(std::string name, const std::vector<std::string>& ports,
                                                 double initial_pressure) {
  ConnectionDescription c;
  c.name = std::move(name);
  for (const auto& p : ports) c.ports.push_back(parse_port_reference(p));
  c.initial_pressure = initial_pressure;
  connections.push_back(std::move(c));
  return connections.back();
}

PortReference parse_port_reference(const std::string& text, SourceMark mark) {
  PortReference ref;
  const auto dot = text.find('.');
  if (dot == std::string::npos) {
    ref.component = text;
  } else {
    ref.component = text.substr(0, dot);
    ref.connector = text.substr(dot + 1);
  }
  ref.mark = std::move(mark);
  return ref;
}

std::vector<double> resolved_parameters(const ComponentDescription& component) {
  const ComponentType* type = find_component_type(component.type);
  std::vector<double> values = type->default_values();
  for (const auto& s : component.parameters)
    values[static_cast<std::size_t>(type->parameter_index(s.name))] = s.value;
  return values;
}

void validate(const PlantDescription& d) {
  if (!(d.solver.max_step > 0.0 && d.solver.max_step <= 0.1))
    fail(d.solver.mark, fmt::format("solver max_step = {} out of range: must be > 0 and <= 0.1 s", d.solver.max_step));

  std::map<std::string, const ComponentDescription*> by_name;
  int fluids = 0;
  for (const auto& c : d.components) {
    const ComponentType* type = find_component_type(c.type);
    if (type == nullptr) fail(c.type_mark, fmt::format("unknown component type '{}'", c.type));
    if (!valid_name(c.name))
      fail(c.name_mark, fmt::format("invalid component name '{}': use letters, digits, '_' and '-'", c.name));
    if (!by_name.emplace(c.name, &c).second) fail(c.name_mark, fmt::format("duplicate component name '{}'", c.name));
    if (c.type == "fluid") ++fluids;
    std::set<std::string> seen;
    for (const auto& s : c.parameters) {
      const int index = type->parameter_index(s.name);
      if (index < 0) fail(s.name_mark, fmt::format("unknown parameter '{}' for component type '{}'", s.name, c.type));
      if (!seen.insert(s.name).second) fail(s.name_mark, fmt::format("parameter '{}' given twice", s.name));
      if (auto why = check_range(type->parameters[static_cast<std::size_t>(index)], s.value); !why.empty())
        fail(s.value_mark, why);
    }
    if (type->check != nullptr) {
      if (auto why = type->check(resolved_parameters(c)); !why.empty()) fail(c.mark, fmt::format("{}: {}", c.name, why));
    }
  }
  if (fluids != 1)
    fail(d.components.empty() ? SourceMark{} : d.components.front().mark,
         fmt::format("a plant needs exactly one component of type 'fluid' (found {})", fluids));

  std::set<std::string> connection_names;
  std::map<std::pair<std::string, std::string>, const PortReference*> used;
  for (const auto& conn : d.connections) {
    if (!valid_name(conn.name))
      fail(conn.mark, fmt::format("invalid connection name '{}': use letters, digits, '_' and '-'", conn.name));
    if (!connection_names.insert(conn.name).second)
      fail(conn.mark, fmt::format("duplicate connection name '{}'", conn.name));
    if (conn.ports.empty()) fail(conn.mark, fmt::format("connection '{}' has no ports", conn.name));
    if (!std::isfinite(conn.initial_pressure))
      fail(conn.mark, fmt::format("connection '{}': initial_pressure must be finite", conn.name));
    const ConnectorSpec* first = nullptr;
    int tanks = 0, owners = 0;
    for (const auto& ref : conn.ports) {
      auto it = by_name.find(ref.component);
      if (it == by_name.end())
        fail(ref.mark, fmt::format("connection '{}': no component named '{}'", conn.name, ref.component));
      const ComponentType* type = find_component_type(it->second->type);
      const int index = type->connector_index(ref.connector);
      if (index < 0)
        fail(ref.mark, fmt::format("connection '{}': component '{}' ({}) has no port '{}'", conn.name, ref.component,
                                   type->name, ref.connector));
      const ConnectorSpec& spec = type->connectors[static_cast<std::size_t>(index)];
      if (auto [pos, fresh] = used.emplace(std::make_pair(ref.component, ref.connector), &ref); !fresh)
        fail(ref.mark, fmt::format("port '{}' is connected twice", ref.to_string()));
      if (first == nullptr) {
        first = &spec;
      } else if (spec.domain != first->domain) {
        fail(ref.mark, fmt::format("connection '{}' mixes fluid ports and shaft couplings ('{}')", conn.name,
                                   ref.to_string()));
      }
      if (type->name == "tank") ++tanks;
      if (spec.owns_body) ++owners;
    }
    if (tanks > 1) fail(conn.mark, fmt::format("connection '{}' joins {} tanks; one fixes the pressure", conn.name, tanks));
    if (first->domain == Domain::Rotational && owners != 1)
      fail(conn.mark, fmt::format("shaft coupling '{}' needs exactly one rotary_shaft flange (found {})", conn.name,
                                  owners));
  }

  for (const auto& c : d.components) {
    const ComponentType* type = find_component_type(c.type);
    for (const auto& spec : type->connectors) {
      if (!used.contains({c.name, std::string(spec.name)}))
        fail(c.mark, fmt::format("port '{}.{}' is not connected", c.name, spec.name));
    }
  }
}

bool equivalent(const PlantDescription& a, const PlantDescription& b) {
  if (a.solver.max_step != b.solver.max_step) return false;
  if (a.components.size() != b.components.size() || a.connections.size() != b.connections.size()) return false;
  for (std::size_t i = 0; i < a.components.size(); ++i) {
    const auto &x = a.components[i], &y = b.components[i];
    if (x.type != y.type || x.name != y.name) return false;
    if (resolved_parameters(x) != resolved_parameters(y)) return false;
  }
  for (std::size_t i = 0; i < a.connections.size(); ++i) {
    const auto &x = a.connections[i], &y = b.connections[i];
    if (x.name != y.name || x.initial_pressure != y.initial_pressure || x.ports.size() != y.ports.size()) return false;
    for (std::size_t k = 0; k < x.ports.size(); ++k)
      if (x.ports[k].to_string() != y.ports[k].to_string()) return false;
  }
  return true;
}

}  // namespace plant
