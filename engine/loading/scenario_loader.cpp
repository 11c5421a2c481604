#include "engine/loading/scenario_loader.h"

#include <set>

#include "engine/loading/script_loader.h"
#include "sim/file_reader.h"
#include "sim/transport_factory.h"

namespace scenario {

namespace {

std::vector<BusSpec> read_buses(const YAML::Node& seq, const std::string& file) {
  std::vector<BusSpec> buses;
  if (!seq.IsSequence()) throw LoadError(mark_of(seq, file), "buses: expected a list of buses");
  for (const auto& item : seq) {
    MapReader r(item, file, "bus");
    BusSpec b;
    b.mark = r.mark();
    b.name = read_name(r.require("name"), file, "bus name");
    for (const auto& other : buses)
      if (other.name == b.name) throw LoadError(r.key_mark("name"), "duplicate bus name '" + b.name + "'");
    if (auto t = r.get("transport")) {
      const auto text = read_string(t, file, "transport");
      if (text == "virtual") {
        b.iface.clear();
      } else if (text.rfind("socketcan:", 0) == 0 && text.size() > 10) {
        b.iface = text.substr(10);
      } else if (sim::is_socketcand_spec(text)) {
        b.iface = text;  // opened by sim::open_transport when the world is built
      } else {
        throw LoadError(mark_of(t, file), "transport: '" + text +
                                              "' is neither 'virtual', 'socketcan:IFACE', 'socketcand:ADDR:PORT' nor "
                                              "'socketcand-client:HOST:PORT/CHANNEL'");
      }
    }
    if (auto br = r.get("bitrate")) {
      static const std::set<std::int64_t> kRates = {10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000};
      const auto v = read_integer(br, file, "bitrate", 10000, 1000000);
      if (!kRates.count(v))
        throw LoadError(mark_of(br, file), "bitrate: " + std::to_string(v) + " is not a CiA 301 bit rate (10k..1M)");
      b.bitrate = static_cast<std::uint32_t>(v);
    }
    if (auto t = r.get("timing")) {
      const auto text = read_string(t, file, "timing");
      if (text == "bit") b.timing = sim::BusTiming::Bit;
      else if (text == "ideal") b.timing = sim::BusTiming::Ideal;
      else throw LoadError(mark_of(t, file), "timing: '" + text + "' is neither 'bit' nor 'ideal'");
    }
    if (auto q = r.get("tx_queue")) b.tx_queue = static_cast<std::size_t>(read_integer(q, file, "tx_queue", 1, 4096));
    r.finish();
    buses.push_back(std::move(b));
  }
  if (buses.empty()) throw LoadError(mark_of(seq, file), "buses: at least one bus is needed");
  return buses;
}

std::string resolve_input(const std::string& dir, const std::string& path) {
  if (path.empty() || path[0] == '/' || dir.empty()) return path;
  return dir + "/" + path;
}

std::vector<NodeSpec> read_nodes(const YAML::Node& seq, const std::string& file, const std::string& dir,
                                 const std::vector<BusSpec>& buses) {
  std::vector<NodeSpec> nodes;
  if (!seq.IsSequence()) throw LoadError(mark_of(seq, file), "nodes: expected a list of nodes");
  for (const auto& item : seq) {
    MapReader r(item, file, "node");
    NodeSpec n;
    n.mark = r.mark();
    n.name = read_name(r.require("name"), file, "node name");
    for (const auto& other : nodes)
      if (other.name == n.name) throw LoadError(r.key_mark("name"), "duplicate node name '" + n.name + "'");
    n.device_mark = r.key_mark("device");
    n.device = read_name(r.require("device"), file, "device");
    if (auto v = r.get("variant")) n.variant = read_string(v, file, "variant");
    if (auto e = r.get("eds")) n.eds = resolve_input(dir, read_string(e, file, "eds"));
    if (n.device == "eds" && n.eds.empty()) throw LoadError(n.device_mark, "device 'eds' needs 'eds: FILE'");
    if (n.device != "eds" && !n.eds.empty()) throw LoadError(r.key_mark("eds"), "'eds' is only for device 'eds'");
    if (auto id = r.get("node_id")) {
      n.node_id_mark = mark_of(id, file);
      n.node_id = static_cast<std::uint8_t>(read_integer(id, file, "node_id", 1, 127));
    }
    if (auto b = r.get("bus")) {
      n.bus = read_name(b, file, "bus");
      bool found = false;
      for (const auto& bus : buses) found |= bus.name == n.bus;
      if (!found) throw LoadError(mark_of(b, file), "unknown bus '" + n.bus + "'");
    } else {
      if (buses.size() > 1) throw LoadError(n.mark, "node '" + n.name + "': several buses, say which with 'bus:'");
      n.bus = buses.front().name;
    }
    if (auto s = r.get("settings")) {
      n.settings_mark = mark_of(s, file);
      MapReader sr(s, file, "settings of node '" + n.name + "'");
      for (const auto& kv : s) {
        const auto key = kv.first.Scalar();
        sr.get(key);
        n.settings[key] = read_string(kv.second, file, "setting '" + key + "'");
      }
      sr.finish();
    }
    if (auto p = r.get("parameters")) {
      MapReader pr(p, file, "parameters of node '" + n.name + "'");
      for (const auto& kv : p) {
        pr.get(kv.first.Scalar());
        ParameterOverride o;
        o.mark = mark_of(kv.first, file);
        parse_object_address(kv.first.Scalar(), o.mark, o.index, o.sub);
        o.value = read_literal(kv.second, file, "parameter " + kv.first.Scalar());
        n.parameters.push_back(std::move(o));
      }
      pr.finish();
    }
    if (auto in = r.get("inputs")) {
      MapReader ir(in, file, "inputs of node '" + n.name + "'");
      for (const auto& kv : in) {
        const auto key = kv.first.Scalar();
        ir.get(key);
        n.inputs.emplace_back(key, read_number(kv.second, file, "input '" + key + "'"));
        n.input_marks.push_back(mark_of(kv.first, file));
      }
      ir.finish();
    }
    if (auto st = r.get("store")) {
      n.store = resolve_input(dir, read_string(st, file, "store"));
      n.store_mark = mark_of(st, file);
    }
    r.finish();
    nodes.push_back(std::move(n));
  }
  return nodes;
}

std::vector<WireSpec> read_wires(const YAML::Node& seq, const std::string& file) {
  std::vector<WireSpec> wires;
  if (!seq.IsSequence()) throw LoadError(mark_of(seq, file), "wires: expected a list of {from, to}");
  for (const auto& item : seq) {
    MapReader r(item, file, "wire");
    WireSpec w;
    w.mark = r.mark();
    const auto from = r.require("from"), to = r.require("to");
    w.from_mark = mark_of(from, file);
    w.to_mark = mark_of(to, file);
    w.from = read_string(from, file, "from");
    w.to = read_string(to, file, "to");
    if (auto s = r.get("scale")) w.scale = read_number(s, file, "scale");
    if (auto o = r.get("offset")) w.offset = read_number(o, file, "offset");
    if (auto n = r.get("noise")) w.noise = read_number(n, file, "noise", 0.0, 1e12);
    r.finish();
    for (const auto& other : wires)
      if (other.to == w.to) throw LoadError(w.to_mark, "input '" + w.to + "' is already driven by '" + other.from + "'");
    wires.push_back(std::move(w));
  }
  return wires;
}

ClockSpec read_clock(const YAML::Node& node, const std::string& file) {
  MapReader r(node, file, "clock");
  ClockSpec c;
  if (auto t = r.get("tick")) {
    c.tick = read_duration(t, file, "tick");
    if (c.tick < sim::microseconds(50) || c.tick > sim::milliseconds(100))
      throw LoadError(mark_of(t, file), "tick: must be between 50us and 100ms");
  }
  if (auto m = r.get("mode")) {
    const auto s = read_string(m, file, "mode");
    if (s == "virtual") c.mode = ClockSpec::Mode::Virtual;
    else if (s == "realtime") c.mode = ClockSpec::Mode::RealTime;
    else throw LoadError(mark_of(m, file), "mode: '" + s + "' is neither 'virtual' nor 'realtime'");
  }
  if (auto d = r.get("duration")) {
    c.duration = read_duration(d, file, "duration");
    if (c.duration->count() <= 0) throw LoadError(mark_of(d, file), "duration: must be greater than zero");
  }
  if (auto s = r.get("seed")) c.seed = static_cast<std::uint64_t>(read_integer(s, file, "seed", 0, INT64_MAX));
  r.finish();
  return c;
}

std::vector<SignalExpr> read_signals(const YAML::Node& n, const std::string& file, std::vector<std::string>* labels) {
  std::vector<SignalExpr> out;
  if (!n.IsSequence()) throw LoadError(mark_of(n, file), "signals: expected a list");
  for (const auto& item : n) {
    if (item.IsMap()) {
      MapReader r(item, file, "signal");
      const auto s = r.require("signal");
      out.push_back(parse_signal(read_string(s, file, "signal"), mark_of(s, file)));
      std::string label;
      if (auto l = r.get("label")) label = read_string(l, file, "label");
      r.finish();
      if (labels) labels->push_back(label);
    } else {
      out.push_back(parse_signal(read_string(item, file, "signal"), mark_of(item, file)));
      if (labels) labels->emplace_back();
    }
  }
  return out;
}

UiSpec read_ui(const YAML::Node& node, const std::string& file) {
  UiSpec u;
  u.mark = mark_of(node, file);
  if (node.IsScalar()) {
    u.listen = read_string(node, file, "ui");
    return u;
  }
  MapReader r(node, file, "ui");
  u.listen = read_string(r.require("listen"), file, "listen");
  if (auto a = r.get("allow_remote")) u.allow_remote = read_bool(a, file, "allow_remote");
  if (auto s = r.get("start")) {
    const auto text = read_string(s, file, "start");
    if (text != "paused" && text != "running") throw LoadError(mark_of(s, file), "start: '" + text + "' is neither 'paused' nor 'running'");
    u.start_paused = text == "paused";
  }
  if (auto sp = r.get("speed")) {
    u.speed = read_number(sp, file, "speed");
    if (u.speed < 0 || u.speed > 1000 || (u.speed > 0 && u.speed < 0.001))
      throw LoadError(mark_of(sp, file), "speed: must be 0 (as fast as possible) or between 0.001 and 1000");
  }
  r.finish();
  return u;
}

// `master_rules: {sync-jitter: off, sdo-abort: warning}`: a severity per rule, by name.
MasterRuleSettings read_master_rules(const YAML::Node& node, const std::string& file) {
  MasterRuleSettings settings;
  settings.mark = mark_of(node, file);
  if (!node.IsMap()) throw LoadError(settings.mark, "master_rules must be a mapping of rule names to off, warning or error");
  std::vector<bool> seen(kMasterRuleCount, false);
  for (const auto& kv : node) {
    const std::string name = read_string(kv.first, file, "master_rules key");
    const auto rule = rule_by_name(name);
    if (!rule) throw LoadError(mark_of(kv.first, file), "unknown master rule '" + name + "' (rules: " + rule_names() + ")");
    if (seen[static_cast<std::size_t>(*rule)]) throw LoadError(mark_of(kv.first, file), "master rule '" + name + "' given twice");
    seen[static_cast<std::size_t>(*rule)] = true;
    const std::string value = read_string(kv.second, file, "master_rules." + name);
    const auto severity = severity_by_name(value);
    if (!severity) throw LoadError(mark_of(kv.second, file), "master_rules." + name + ": '" + value + "' is not off, warning or error");
    settings.severity[static_cast<std::size_t>(*rule)] = *severity;
  }
  return settings;
}

OutputSpec read_outputs(const YAML::Node& node, const std::string& file) {
  MapReader r(node, file, "outputs");
  OutputSpec o;
  if (auto t = r.get("trace")) o.trace = read_string(t, file, "trace");
  if (auto p = r.get("sample_period")) o.sample_period = read_period(p, file, "sample_period");
  if (auto c = r.get("csv")) {
    CsvSpec csv;
    if (c.IsScalar()) {
      csv.file = read_string(c, file, "csv");
    } else {
      MapReader cr(c, file, "csv");
      csv.file = read_string(cr.require("file"), file, "csv file");
      if (auto s = cr.get("signals")) csv.signals = read_signals(s, file, nullptr);
      cr.finish();
    }
    o.csv = std::move(csv);
  }
  if (auto pl = r.get("plots")) {
    if (!pl.IsSequence()) throw LoadError(mark_of(pl, file), "plots: expected a list of plots");
    for (const auto& item : pl) {
      MapReader pr(item, file, "plot");
      PlotSpec p;
      p.mark = pr.mark();
      // Plots are drawn in the HTML report (--report DIR); vplant writes no image files.
      if (auto f = pr.get("file")) throw LoadError(mark_of(f, file), "plot: 'file' is gone: plots are drawn in the HTML report (vplant run --report DIR)");
      if (auto t = pr.get("title")) p.title = read_string(t, file, "title");
      if (auto y = pr.get("y_label")) p.y_label = read_string(y, file, "y_label");
      p.signals = read_signals(pr.require("signals"), file, &p.labels);
      if (p.signals.empty()) throw LoadError(p.mark, "plot: at least one signal");
      if (p.signals.size() > 8) throw LoadError(p.mark, "plot: at most 8 signals");
      pr.finish();
      o.plots.push_back(std::move(p));
    }
  }
  if (auto j = r.get("junit")) o.junit = read_string(j, file, "junit");
  r.finish();
  return o;
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& file, const std::string& dir) {
  return parse_scenario_node(parse_yaml(text, file), file, dir);
}

Scenario parse_scenario_node(const YAML::Node& root, const std::string& file, const std::string& dir) {
  Scenario s;
  s.file = file;
  s.dir = dir;
  if (!root.IsDefined() || root.IsNull()) throw LoadError(SourceMark{file, 1, 1}, "empty scenario file");
  MapReader r(root, file, "scenario");
  if (auto n = r.get("name")) s.name = read_string(n, file, "name");
  if (auto d = r.get("description")) s.description = read_string(d, file, "description");
  if (auto b = r.get("buses")) {
    s.buses = read_buses(b, file);
  } else {
    BusSpec main;
    main.name = "main";
    main.mark = r.mark();
    s.buses.push_back(main);
  }
  if (auto n = r.get("nodes")) s.nodes = read_nodes(n, file, dir, s.buses);
  if (auto p = r.get("plant")) {
    s.plant = p;
    s.has_plant = true;
    s.plant_mark = mark_of(p, file);
  }
  if (auto w = r.get("wires")) s.wires = read_wires(w, file);
  s.clock.mark = r.mark();
  if (auto c = r.get("clock")) {
    s.clock = read_clock(c, file);
    s.clock.mark = mark_of(c, file);
  }
  if (auto o = r.get("outputs")) s.outputs = read_outputs(o, file);
  if (auto sc = r.get("script")) s.script = read_script(sc, file);
  if (auto f = r.get("faults")) s.faults = read_faults(f, file);
  if (auto u = r.get("ui")) s.ui = read_ui(u, file);
  r.get("matrix");  // the sweep: expanded before this by ScenarioCases (scenario_cases.h)
  if (auto m = r.get("master_rules")) s.master_rules = read_master_rules(m, file);
  r.finish();
  if (s.name.empty()) {
    const auto slash = file.rfind('/');
    s.name = file.substr(slash == std::string::npos ? 0 : slash + 1);
    if (const auto dot = s.name.rfind(".yaml"); dot != std::string::npos) s.name.resize(dot);
  }
  return s;
}

std::string read_scenario_file(const std::string& path, std::string& dir) {
  std::string text, reason;
  switch (sim::read_input_file(path, text, reason)) {
    case sim::ReadStatus::Ok: break;
    case sim::ReadStatus::Missing: throw LoadError(SourceMark{path, 0, 0}, "cannot open the scenario file");
    case sim::ReadStatus::Failed: throw LoadError(SourceMark{path, 0, 0}, reason);
  }
  const auto slash = path.rfind('/');
  dir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
  return text;
}

Scenario load_scenario_file(const std::string& path) {
  std::string dir;
  const std::string text = read_scenario_file(path, dir);
  return parse_scenario(text, path, dir);
}

}  // namespace scenario
