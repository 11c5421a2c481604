#include "engine/loading/scenario_cases.h"

#include <set>

#include "engine/loading/scenario_loader.h"
#include "engine/loading/yaml_fields.h"

namespace scenario {

namespace {

std::vector<std::string> split_path(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

/// The item of a list whose `name:` is `name` (an invalid node when none is).
YAML::Node named_item(const YAML::Node& list, const std::string& name) {
  for (const auto& item : list)
    if (item.IsMap() && item["name"] && item["name"].IsScalar() && item["name"].Scalar() == name) return item;
  return YAML::Node(YAML::NodeType::Undefined);
}

/// parts[from] . ... . parts[to - 1]
std::string joined(const std::vector<std::string>& parts, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t i = from; i < to; ++i) out += (i > from ? "." : "") + parts[i];
  return out;
}

/// Writes `value` at `key` in the document. `key_node` is the matrix's key: when the last key
/// does not exist yet, it becomes that key (relabelled), so an error about it points at the
/// matrix. Throws LoadError at the matrix key when the path leads nowhere.
void write_at(YAML::Node root, const std::string& key, YAML::Node key_node, const YAML::Node& value,
              const std::string& file) {
  const SourceMark mark = mark_of(key_node, file);
  const auto parts = split_path(key);
  auto fail = [&](const std::string& why) { throw LoadError(mark, "matrix: '" + key + "': " + why); };
  YAML::Node parent = root;
  std::string last;
  if (parts[0] == "plant") {
    // plant.COMPONENT.PARAMETER: the reference plant's `parameters:` (keys `component.parameter`)
    // or, in the plant's own format, the component's `parameters:`.
    if (parts.size() != 3) fail("a plant parameter is plant.COMPONENT.PARAMETER");
    const YAML::Node plant = static_cast<const YAML::Node&>(root)["plant"];
    if (!plant || !plant.IsMap()) fail("the scenario has no plant");
    YAML::Node holder;  // YAML::Node's operator= writes into the node: reset() rebinds the handle
    if (plant["reference"]) {
      holder.reset(plant);
      last = joined(parts, 1, parts.size());
    } else {
      const YAML::Node components = plant["components"];
      if (!components || !components.IsSequence()) fail("the plant has no list of components");
      holder.reset(named_item(components, parts[1]));
      if (!holder) fail("the plant has no component named '" + parts[1] + "'");
      last = parts[2];
    }
    if (!holder["parameters"]) holder["parameters"] = YAML::Node(YAML::NodeType::Map);
    parent.reset(holder["parameters"]);
    if (!parent.IsMap()) fail("the plant's parameters are not a mapping");
  } else {
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      const std::string where = joined(parts, 0, i + 1);
      YAML::Node next(YAML::NodeType::Undefined);
      const YAML::Node& lookup = parent;  // const: looking up does not add the key
      if (parent.IsMap()) {
        if (const YAML::Node found = lookup[parts[i]]) next.reset(found);  // a missing key is an invalid node
      } else if (parent.IsSequence()) {
        next.reset(named_item(parent, parts[i]));
      }
      if (!next) fail(parent.IsSequence() ? "no item named '" + parts[i] + "' in the list" : "the scenario has no '" + where + "'");
      if (!next.IsMap() && !next.IsSequence()) fail("'" + where + "' is a single value, not a mapping or a list");
      parent.reset(next);
    }
    last = parts.back();
    if (!parent.IsMap()) fail("a whole list item cannot be varied, only its keys");
  }
  for (auto kv : parent) {
    if (kv.first.IsScalar() && kv.first.Scalar() == last) {
      kv.second = value;  // shares the matrix value's node: errors point at it
      return;
    }
  }
  key_node = last;  // the matrix key, relabelled, keeps its line and column
  parent[key_node] = value;
}

/// Characters a file name may take from a value; others become '_'.
std::string file_safe(const std::string& text) {
  std::string out = text;
  for (char& c : out) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
                    c == '-' || c == '=' || c == ',' || c == '+';
    if (!ok) c = '_';
  }
  return out;
}

/// `out/ref.log` → `out/ref.SUFFIX.log`; `out/trace` → `out/trace.SUFFIX`.
std::string with_suffix(const std::string& path, const std::string& suffix) {
  if (path.empty() || suffix.empty()) return path;
  const auto slash = path.rfind('/');
  const auto dot = path.rfind('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  return has_ext ? path.substr(0, dot) + "." + suffix + path.substr(dot) : path + "." + suffix;
}

}  // namespace

ScenarioCases::ScenarioCases(std::string text, std::string file, std::string dir)
    : text_(std::move(text)), file_(std::move(file)), dir_(std::move(dir)) {}

ScenarioCases ScenarioCases::load_file(const std::string& path) {
  std::string dir;
  std::string text = read_scenario_file(path, dir);
  return parse(std::move(text), path, dir);
}

ScenarioCases ScenarioCases::parse(const std::string& text, const std::string& file, const std::string& dir) {
  ScenarioCases c(text, file, dir);
  const YAML::Node root = parse_yaml(text, file);
  if (root.IsMap() && root["matrix"]) {
    const YAML::Node matrix = root["matrix"];
    MapReader r(matrix, file, "matrix");
    std::size_t combinations = 1;
    for (const auto& kv : matrix) {
      Axis axis;
      axis.key = kv.first.Scalar();
      axis.mark = mark_of(kv.first, file);
      r.get(axis.key);
      const auto parts = split_path(axis.key);
      for (const auto& part : parts)
        if (part.empty()) throw LoadError(axis.mark, "matrix: '" + axis.key + "' is not a dotted path of keys");
      if (parts[0] == "name" || parts[0] == "matrix")
        throw LoadError(axis.mark, "matrix: '" + parts[0] + "' cannot be varied");
      if (!kv.second.IsSequence() || kv.second.size() == 0)
        throw LoadError(mark_of(kv.second, file), "matrix: '" + axis.key + "': expected a non-empty list of values");
      std::set<std::string> seen;
      for (const auto& v : kv.second) {
        if (!v.IsScalar()) throw LoadError(mark_of(v, file), "matrix: '" + axis.key + "': a value must be a single value");
        if (!seen.insert(v.Scalar()).second)
          throw LoadError(mark_of(v, file), "matrix: '" + axis.key + "': value '" + v.Scalar() + "' is given twice");
        axis.values.push_back(v.Scalar());
      }
      combinations *= axis.values.size();
      if (combinations > kMaxMatrixCases)
        throw LoadError(mark_of(matrix, file), "matrix: more than " + std::to_string(kMaxMatrixCases) + " combinations");
      c.axes_.push_back(std::move(axis));
    }
    if (c.axes_.empty()) throw LoadError(mark_of(matrix, file), "matrix: expected at least one key with a list of values");
  }
  std::size_t total = 1;
  for (const auto& axis : c.axes_) total *= axis.values.size();
  c.values_.reserve(total);
  for (std::size_t i = 0; i < total; ++i) {
    std::string values;
    const auto pick = c.choice(i);
    for (std::size_t a = 0; a < c.axes_.size(); ++a)
      values += (a ? "," : "") + c.axes_[a].key + "=" + c.axes_[a].values[pick[a]];
    c.values_.push_back(std::move(values));
  }
  c.first_ = c.load(0);  // checks the whole file and every matrix key; gives the scenario's name
  const std::string& named = c.first_->name;  // `<name>[values of case 0]` with a matrix
  const std::string base = named.substr(0, named.size() - (c.axes_.empty() ? 0 : c.values_[0].size() + 2));
  c.names_.reserve(total);
  for (const auto& values : c.values_) c.names_.push_back(c.axes_.empty() ? base : base + "[" + values + "]");
  return c;
}

std::vector<std::size_t> ScenarioCases::choice(std::size_t i) const {
  std::vector<std::size_t> pick(axes_.size());
  for (std::size_t a = axes_.size(); a-- > 0;) {
    pick[a] = i % axes_[a].values.size();
    i /= axes_[a].values.size();
  }
  return pick;
}

std::optional<std::size_t> ScenarioCases::find(const std::string& name) const {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return i;
  return std::nullopt;
}

Scenario ScenarioCases::load(std::size_t i) const {
  if (i == 0 && first_) return *first_;
  YAML::Node root = parse_yaml(text_, file_);
  if (!axes_.empty()) {
    // Every key and value node first: relabelling a key below changes the matrix mapping.
    std::vector<std::pair<YAML::Node, YAML::Node>> entries;
    for (auto kv : root["matrix"]) entries.emplace_back(kv.first, kv.second);
    const auto pick = choice(i);
    for (std::size_t a = 0; a < axes_.size(); ++a)
      write_at(root, axes_[a].key, entries[a].first, entries[a].second[pick[a]], file_);
  }
  Scenario s = parse_scenario_node(root, file_, dir_);
  if (axes_.empty()) return s;
  s.name += "[" + values_[i] + "]";
  for (std::string* path : {&s.outputs.trace, &s.outputs.junit}) *path = output_path(*path, i);
  if (s.outputs.csv) s.outputs.csv->file = output_path(s.outputs.csv->file, i);
  return s;
}

std::string ScenarioCases::output_path(const std::string& path, std::size_t i) const {
  return axes_.empty() ? path : with_suffix(path, file_safe(values_[i]));
}

}  // namespace scenario
