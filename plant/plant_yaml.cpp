#include "plant/plant_yaml.h"

#include <fmt/format.h>

#include <cmath>
#include <initializer_list>
#include <string_view>

#include <yaml-cpp/depthguard.h>

#include "sim/file_reader.h"

namespace plant {
namespace {

SourceMark mark_of(const YAML::Mark& m, const std::string& file) {
  if (m.line < 0) return SourceMark{file, 0, 0};
  return SourceMark{file, m.line + 1, m.column + 1};
}

class Reader {
 public:
  explicit Reader(const std::string& file) : file_(file) {}

  SourceMark mark(const YAML::Node& n) const { return mark_of(n.Mark(), file_); }

  [[noreturn]] void fail(const YAML::Node& n, std::string reason) const {
    throw DescriptionError(Diagnostic{mark(n), std::move(reason)});
  }

  void expect_map(const YAML::Node& n, std::string_view what) const {
    if (!n.IsMap()) fail(n, fmt::format("{} must be a mapping", what));
  }
  void expect_sequence(const YAML::Node& n, std::string_view what) const {
    if (!n.IsSequence()) fail(n, fmt::format("{} must be a list", what));
  }

  /// Rejects keys other than `allowed` (a misspelt key must not be silently ignored).
  void only_keys(const YAML::Node& map, std::initializer_list<std::string_view> allowed, std::string_view where) const {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string key = it->first.Scalar();
      bool ok = false;
      for (auto a : allowed) ok = ok || key == a;
      if (!ok) fail(it->first, fmt::format("unknown key '{}' in {}", key, where));
    }
  }

  std::string text(const YAML::Node& n, std::string_view what) const {
    if (!n.IsScalar()) fail(n, fmt::format("{} must be a string", what));
    return n.Scalar();
  }

  /// A number in SI units; `true`/`false` are accepted for flags and read as 1/0.
  double number(const YAML::Node& n, std::string_view what) const {
    if (!n.IsScalar()) fail(n, fmt::format("{} must be a number", what));
    double value = 0.0;
    bool flag = false;
    if (YAML::convert<double>::decode(n, value)) {
      if (!std::isfinite(value)) fail(n, fmt::format("{} must be a finite number", what));
      return value;
    }
    if (YAML::convert<bool>::decode(n, flag)) return flag ? 1.0 : 0.0;
    fail(n, fmt::format("{} must be a number in SI units, got '{}'", what, n.Scalar()));
  }

  YAML::Node required(const YAML::Node& map, const char* key, std::string_view where) const {
    YAML::Node n = map[key];
    if (!n) fail(map, fmt::format("{} needs a '{}'", where, key));
    return n;
  }

 private:
  const std::string& file_;
};

}  // namespace

PlantDescription parse_plant_description(const YAML::Node& plant, const std::string& file) {
  const Reader r(file);
  r.expect_map(plant, "the plant section");
  r.only_keys(plant, {"solver", "components", "connections"}, "the plant section");
  PlantDescription d;

  if (const YAML::Node solver = plant["solver"]) {
    r.expect_map(solver, "plant.solver");
    r.only_keys(solver, {"max_step"}, "plant.solver");
    if (const YAML::Node step = solver["max_step"]) {
      d.solver.max_step = r.number(step, "max_step");
      d.solver.mark = r.mark(step);
    }
  }

  const YAML::Node components = r.required(plant, "components", "the plant section");
  r.expect_sequence(components, "plant.components");
  for (const YAML::Node& item : components) {
    r.expect_map(item, "a component");
    r.only_keys(item, {"type", "name", "parameters"}, "a component");
    ComponentDescription c;
    c.mark = r.mark(item);
    const YAML::Node type = r.required(item, "type", "a component");
    c.type = r.text(type, "type");
    c.type_mark = r.mark(type);
    const YAML::Node name = r.required(item, "name", "a component");
    c.name = r.text(name, "name");
    c.name_mark = r.mark(name);
    if (const YAML::Node params = item["parameters"]) {
      r.expect_map(params, "parameters");
      for (auto it = params.begin(); it != params.end(); ++it) {
        ParameterSetting s;
        s.name = r.text(it->first, "a parameter name");
        s.name_mark = r.mark(it->first);
        s.value = r.number(it->second, fmt::format("parameter '{}'", s.name));
        s.value_mark = r.mark(it->second);
        c.parameters.push_back(std::move(s));
      }
    }
    d.components.push_back(std::move(c));
  }

  if (const YAML::Node connections = plant["connections"]) {
    r.expect_sequence(connections, "plant.connections");
    for (const YAML::Node& item : connections) {
      r.expect_map(item, "a connection");
      r.only_keys(item, {"name", "ports", "initial_pressure"}, "a connection");
      ConnectionDescription c;
      c.mark = r.mark(item);
      c.name = r.text(r.required(item, "name", "a connection"), "name");
      const YAML::Node ports = r.required(item, "ports", "a connection");
      r.expect_sequence(ports, "ports");
      for (const YAML::Node& port : ports) {
        const std::string text = r.text(port, "a port");
        if (text.find('.') == std::string::npos)
          r.fail(port, fmt::format("port '{}' must be written component.port", text));
        c.ports.push_back(parse_port_reference(text, r.mark(port)));
      }
      if (const YAML::Node p0 = item["initial_pressure"]) c.initial_pressure = r.number(p0, "initial_pressure");
      d.connections.push_back(std::move(c));
    }
  }

  validate(d);
  return d;
}

PlantDescription load_plant_file(const std::string& path) {
  std::string text, reason;
  switch (sim::read_input_file(path, text, reason)) {
    case sim::ReadStatus::Ok: break;
    case sim::ReadStatus::Missing: throw DescriptionError(Diagnostic{SourceMark{path, 0, 0}, "cannot open: no such file"});
    case sim::ReadStatus::Failed: throw DescriptionError(Diagnostic{SourceMark{path, 0, 0}, reason});
  }
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw DescriptionError(Diagnostic{mark_of(e.mark, path),
                                      "nesting deeper than " + std::to_string(e.depth() - 1) + " levels (the YAML parser's limit)"});
  } catch (const YAML::ParserException& e) {
    throw DescriptionError(Diagnostic{mark_of(e.mark, path), e.msg});
  }
  if (!root.IsMap() || !root["plant"])
    throw DescriptionError(Diagnostic{mark_of(root.Mark(), path), "expected a top-level 'plant:' section"});
  return parse_plant_description(root["plant"], path);
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
