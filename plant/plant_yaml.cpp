#include "plant/plant_yaml.h"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <string_view>

#include "sim/file_reader.h"
#include "sim/yaml_fields.h"

namespace plant {
namespace {

using sim::MapReader;
using sim::mark_of;
using sim::read_string;

[[noreturn]] void fail(const YAML::Node& n, const std::string& file, std::string reason) {
  throw DescriptionError(mark_of(n, file), std::move(reason));
}

void expect_list(const YAML::Node& n, const std::string& file, std::string_view what) {
  if (!n.IsSequence()) fail(n, file, fmt::format("{}: expected a list of {}", what, what));
}

/// A number in SI units; a flag's words (true/false, yes/no, on/off) are read as 1/0.
double number(const YAML::Node& n, const std::string& file, std::string_view what) {
  static constexpr std::string_view kFlagWords[] = {"true", "false", "yes", "no", "on", "off"};
  if (n.IsScalar() && std::find(std::begin(kFlagWords), std::end(kFlagWords), n.Scalar()) != std::end(kFlagWords))
    return sim::read_bool(n, file, what) ? 1.0 : 0.0;
  return sim::read_number(n, file, what);
}

}  // namespace

PlantDescription parse_plant_description(const YAML::Node& plant, const std::string& file) {
  MapReader r(plant, file, "plant");
  PlantDescription d;

  if (const YAML::Node solver = r.get("solver")) {
    MapReader sr(solver, file, "plant.solver");
    if (const YAML::Node step = sr.get("max_step")) {
      d.solver.max_step = number(step, file, "max_step");
      d.solver.mark = mark_of(step, file);
    }
    sr.finish();
  }

  const YAML::Node components = r.require("components");
  expect_list(components, file, "components");
  for (const YAML::Node& item : components) {
    MapReader cr(item, file, "a component");
    ComponentDescription c;
    c.mark = mark_of(item, file);
    const YAML::Node type = cr.require("type");
    c.type = read_string(type, file, "type");
    c.type_mark = mark_of(type, file);
    const YAML::Node name = cr.require("name");
    c.name = read_string(name, file, "name");
    c.name_mark = mark_of(name, file);
    if (const YAML::Node params = cr.get("parameters")) {
      // Any name here; validate() checks it against the component's type.
      const MapReader pr(params, file, "parameters");
      for (const auto& kv : pr.node()) {
        ParameterSetting s;
        s.name = read_string(kv.first, file, "a parameter name");
        s.name_mark = mark_of(kv.first, file);
        s.value = number(kv.second, file, fmt::format("parameter '{}'", s.name));
        s.value_mark = mark_of(kv.second, file);
        c.parameters.push_back(std::move(s));
      }
    }
    cr.finish();
    d.components.push_back(std::move(c));
  }

  if (const YAML::Node connections = r.get("connections")) {
    expect_list(connections, file, "connections");
    for (const YAML::Node& item : connections) {
      MapReader cr(item, file, "a connection");
      ConnectionDescription c;
      c.mark = mark_of(item, file);
      c.name = read_string(cr.require("name"), file, "name");
      const YAML::Node ports = cr.require("ports");
      expect_list(ports, file, "ports");
      for (const YAML::Node& port : ports) {
        const std::string text = read_string(port, file, "a port");
        if (text.find('.') == std::string::npos)
          fail(port, file, fmt::format("port '{}' must be written component.port", text));
        c.ports.push_back(parse_port_reference(text, mark_of(port, file)));
      }
      if (const YAML::Node p0 = cr.get("initial_pressure")) c.initial_pressure = number(p0, file, "initial_pressure");
      cr.finish();
      d.connections.push_back(std::move(c));
    }
  }
  r.finish();

  validate(d);
  return d;
}

PlantDescription load_plant_file(const std::string& path) {
  std::string text, reason;
  switch (sim::read_input_file(path, text, reason)) {
    case sim::ReadStatus::Ok: break;
    case sim::ReadStatus::Missing: throw DescriptionError(SourceMark{path, 0, 0}, "cannot open: no such file");
    case sim::ReadStatus::Failed: throw DescriptionError(SourceMark{path, 0, 0}, reason);
  }
  const YAML::Node root = sim::parse_yaml(text, path);
  MapReader top(root, path, "a plant file");
  const YAML::Node plant = top.require("plant");  // other top-level keys are not the plant's
  return parse_plant_description(plant, path);
}

std::string to_yaml(const PlantDescription& d) {
  std::string out = "plant:\n";
  out += fmt::format("  solver:\n    max_step: {}\n", d.solver.max_step);
  out += "  components:\n";
  for (const auto& c : d.components) {
    out += fmt::format("    - type: {}\n      name: {}\n", c.type, c.name);
    if (!c.parameters.empty()) {
      out += "      parameters:\n";
      for (const auto& p : c.parameters) out += fmt::format("        {}: {}\n", p.name, p.value);
    }
  }
  out += "  connections:\n";
  for (const auto& c : d.connections) {
    out += fmt::format("    - name: {}\n      ports: [", c.name);
    for (std::size_t i = 0; i < c.ports.size(); ++i) out += (i > 0 ? ", " : "") + c.ports[i].to_string();
    out += "]\n";
    if (c.initial_pressure != 0.0) out += fmt::format("      initial_pressure: {}\n", c.initial_pressure);
  }
  return out;
}

}  // namespace plant
