#include "engine/running/world.h"

#include <cstdio>

#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/parameter_store.h"
#include "devices/generic/eds_node.h"
#include "sim/transport_factory.h"
#include "engine/loading/value_codec.h"

namespace scenario {

namespace {

std::string port_names(const sim::PortList& ports, const std::string& prefix) {
  std::string s;
  for (const auto& p : ports) s += (s.empty() ? "" : ", ") + prefix + p.name;
  return s.empty() ? "none" : s;
}

}  // namespace

World::World(const Scenario& scenario, const Environment& env, const BuildOptions& options, std::uint64_t seed)
    : scenario_(scenario), random_(seed) {
  build_buses(options);
  build_nodes(env, options.strict_eds);
  build_plant(env);
  build_wires();
}

int World::bus_index(const std::string& name) const {
  if (name.empty()) return 0;
  for (std::size_t i = 0; i < scenario_.buses.size(); ++i)
    if (scenario_.buses[i].name == name) return static_cast<int>(i);
  return -1;
}

bool World::any_socketcan() const {
  for (const auto& b : buses_)
    if (b->transport()) return true;
  return false;
}

void World::build_buses(const BuildOptions& options) {
  for (const auto& [name, iface] : options.can) {
    if (bus_index(name) < 0 || name.empty())
      throw LoadError(SourceMark{scenario_.file, 0, 0}, "--can " + name + "=" + iface + ": the scenario has no bus '" + name + "'");
  }
  for (const auto& spec : scenario_.buses) {
    std::string iface = spec.iface;
    if (auto it = options.can.find(spec.name); it != options.can.end()) iface = it->second;
    auto bus = std::make_unique<sim::Bus>(spec.name);
    // A SocketCAN bus (or a remote socketcand bus) is timed by the real wire; the in-process bus
    // and one served to socketcand clients need the model.
    const bool modelled = iface.empty() || sim::is_socketcand_server_spec(iface);
    bus->set_timing(modelled ? spec.timing : sim::BusTiming::Ideal, spec.bitrate);
    bus->set_tx_queue_depth(spec.tx_queue);
    if (!iface.empty()) {
      std::string error;
      auto transport = sim::open_transport(spec.name, iface, error);
      if (!transport) throw LoadError(spec.mark, "bus '" + spec.name + "': " + error);
      bus->set_transport(std::move(transport));
    }
    buses_.push_back(std::move(bus));
  }
}

void World::build_nodes(const Environment& env, bool strict_eds) {
  nodes_.reserve(scenario_.nodes.size());
  for (const auto& spec : scenario_.nodes) {
    devices::DeviceOptions options;
    options.node_id = spec.node_id;
    options.variant = spec.variant;
    options.settings = spec.settings;
    options.store_path = spec.store;
    options.strict_eds = strict_eds;
    std::vector<std::string> warnings;
    options.warnings = &warnings;
    std::string error;
    if (!spec.store.empty()) {
      // The file is read again at power-on; reading it now turns a bad one into a load error.
      canopen::ParameterStore probe(spec.store);
      if (!probe.load(error)) throw LoadError(spec.store_mark, "node '" + spec.name + "': store: " + error);
    }
    NodeInstance inst;
    inst.spec = &spec;
    if (spec.device == "eds") {
      inst.device = devices::EdsNode::load(spec.eds, options, error);
    } else {
      const devices::Product* product = env.find_product ? env.find_product(spec.device) : nullptr;
      if (!product) {
        std::string known;
        if (env.product_names)
          for (const auto& n : env.product_names()) known += (known.empty() ? "" : ", ") + n;
        throw LoadError(spec.device_mark, "unknown device type '" + spec.device + "' (known: " +
                                              (known.empty() ? "none in this build" : known) + ", eds)");
      }
      if (!spec.variant.empty() && !product->variants.empty()) {
        bool ok = false;
        for (const auto& v : product->variants) ok |= v == spec.variant;
        if (!ok) {
          std::string list;
          for (const auto& v : product->variants) list += (list.empty() ? "" : ", ") + v;
          throw LoadError(spec.device_mark, "device '" + spec.device + "' has no variant '" + spec.variant + "' (variants: " + list + ")");
        }
      }
      inst.device = product->make(options, error);
    }
    if (!inst.device) throw LoadError(spec.settings.empty() ? spec.mark : spec.settings_mark, "node '" + spec.name + "': " + error);
    for (const auto& w : warnings) {
      warnings_.push_back(spec.settings_mark.to_string() + ": warning: node '" + spec.name + "': " + w);
      std::fprintf(stderr, "%s\n", warnings_.back().c_str());
    }

    inst.bus = bus_index(spec.bus);
    auto& node = inst.device->node();
    inst.node_id = node.node_id() != 0 && node.node_id() != canopen::Node::kUnconfigured ? node.node_id()
                                                                                          : node.pending_node_id();
    for (const auto& other : nodes_) {
      if (other.bus == inst.bus && other.node_id == inst.node_id && inst.node_id != canopen::Node::kUnconfigured)
        throw LoadError(spec.node_id_mark.line ? spec.node_id_mark : spec.mark,
                        "node-ID " + std::to_string(inst.node_id) + " is already used by node '" + other.spec->name +
                            "' on bus '" + spec.bus + "'");
    }

    // Parameter overrides: the node's non-volatile memory at every power-on.
    for (const auto& o : spec.parameters) {
      const canopen::OdEntry* e = node.od().entry(o.index, o.sub);
      if (!e) throw LoadError(o.mark, "node '" + spec.name + "' has no object " + object_address(o.index, o.sub));
      if (!e->writable()) throw LoadError(o.mark, object_address(o.index, o.sub) + " of node '" + spec.name + "' is not writable");
      std::vector<std::uint8_t> bytes;
      if (auto err = encode_literal(e->type, o.value, bytes); !err.empty())
        throw LoadError(o.value.mark, object_address(o.index, o.sub) + ": " + err);
      if (!canopen::is_variable_length(e->type)) {
        if ((e->low_limit && canopen::compare_values(e->type, bytes, *e->low_limit) < 0) ||
            (e->high_limit && canopen::compare_values(e->type, bytes, *e->high_limit) > 0))
          throw LoadError(o.value.mark, object_address(o.index, o.sub) + ": value " + o.value.text + " out of range [" +
                                            (e->low_limit ? describe_bytes(e->type, *e->low_limit) : "-") + ", " +
                                            (e->high_limit ? describe_bytes(e->type, *e->high_limit) : "-") + "]");
      }
      node.policy().store.preset.push_back({o.index, o.sub, bytes});
    }
    for (std::size_t i = 0; i < spec.inputs.size(); ++i) {
      if (auto err = inst.device->set_input(spec.inputs[i].first, spec.inputs[i].second); !err.empty())
        throw LoadError(spec.input_marks[i], "node '" + spec.name + "': " + err);
    }
    node.attach(*buses_[static_cast<std::size_t>(inst.bus)]);
    inst.ports = inst.device->ports();
    nodes_.push_back(std::move(inst));
  }
}

void World::build_plant(const Environment& env) {
  if (!scenario_.has_plant) return;
  if (!env.make_plant) throw LoadError(scenario_.plant_mark, "this build of vplant has no plant physics (plant/)");
  plant_ = env.make_plant(scenario_.plant, scenario_.file);
  for (const auto& p : plant_->ports()) {
    const auto owner = p.name.substr(0, p.name.find('.'));
    for (const auto& n : nodes_)
      if (n.spec->name == owner)
        throw LoadError(n.spec->mark, "node name '" + owner + "' is also a plant component: signal names would clash");
  }
}

World::PortRef World::find_port(const std::string& qualified, const SourceMark& mark) const {
  const auto dot = qualified.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == qualified.size())
    throw LoadError(mark, "'" + qualified + "' is not a port name (node.port or component.signal)");
  const std::string owner = qualified.substr(0, dot);
  const std::string rest = qualified.substr(dot + 1);
  for (const auto& n : nodes_) {
    if (n.spec->name != owner) continue;
    if (const auto* p = sim::find_port(n.ports, rest)) return {p, false};
    throw LoadError(mark, "node '" + owner + "' has no port '" + rest + "' (ports: " + port_names(n.ports, owner + ".") + ")");
  }
  if (plant_) {
    if (const auto* p = sim::find_port(plant_->ports(), qualified)) return {p, true};
    std::string same;
    for (const auto& p : plant_->ports())
      if (p.name.rfind(owner + ".", 0) == 0) same += (same.empty() ? "" : ", ") + p.name;
    if (!same.empty()) throw LoadError(mark, "plant component '" + owner + "' has no signal '" + rest + "' (signals: " + same + ")");
  }
  throw LoadError(mark, "no port '" + qualified + "': '" + owner + "' is neither a node nor a plant component");
}

void World::build_wires() {
  for (const auto& w : scenario_.wires) {
    const auto from = find_port(w.from, w.from_mark);
    const auto to = find_port(w.to, w.to_mark);
    if (from.port->direction != sim::PortDirection::Output)
      throw LoadError(w.from_mark, "'" + w.from + "' is an input; a wire goes from an output");
    if (to.port->direction != sim::PortDirection::Input)
      throw LoadError(w.to_mark, "'" + w.to + "' is an output; a wire goes to an input");
    const WireSet::Link link{from.port->value, to.port->value, w.scale, w.offset, w.noise};
    // Plant outputs feed the devices before they step; device outputs feed the plant after.
    (from.on_plant ? plant_to_devices_ : devices_to_plant_).add(link);
  }
}

NodeInstance* World::find_node(const std::string& name) {
  for (auto& n : nodes_)
    if (n.spec->name == name) return &n;
  return nullptr;
}

NodeInstance* World::find_node(int bus, std::uint8_t node_id) {
  for (auto& n : nodes_)
    if (n.bus == bus && n.device->node().node_id() == node_id) return &n;
  return nullptr;
}

Signal World::resolve(const SignalExpr& e) {
  Signal s = resolve_term(e);
  for (const auto& term : e.more) s.add_term(resolve_term(term));
  return s;
}

Signal World::resolve_term(const SignalExpr& e) {
  if (e.kind == SignalExpr::Kind::Frame) {
    const int bus = bus_index(e.frame.bus);
    if (bus < 0) throw LoadError(e.mark, "signal '" + e.text + "': unknown bus '" + e.frame.bus + "'");
    const int slot = frame_fields_.slot(bus, e.frame.id, e.frame.extended);
    return Signal::frame(&frame_fields_, slot, e.frame, e.scale, e.offset, e.text);
  }
  if (e.owner == "bus" && !find_node("bus")) return resolve_bus_signal(e);
  if (e.port == "nmt_state") {
    if (auto* n = find_node(e.owner)) {
      if (!sim::find_port(n->ports, "nmt_state")) return Signal::nmt_state(&n->device->node(), e.scale, e.offset, e.text);
    }
  }
  const auto ref = find_port(e.qualified_port(), e.mark);
  return Signal::port(ref.port->value, e.scale, e.offset, e.text);
}

Signal World::resolve_bus_signal(const SignalExpr& e) {
  // bus.NAME.load | bus.NAME.NODE.tec | .rec | .error_state
  const auto dot = e.port.find('.');
  const std::string bus_name = e.port.substr(0, dot);
  const int bus = dot == std::string::npos ? -1 : bus_index(bus_name);
  if (bus < 0 || bus_name.empty())
    throw LoadError(e.mark, "signal '" + e.text + "': expected bus.NAME.load or bus.NAME.NODE.tec|rec|error_state with a known bus");
  const auto* b = buses_[static_cast<std::size_t>(bus)].get();
  const std::string rest = e.port.substr(dot + 1);
  if (rest == "load") return Signal::bus_load(b, e.scale, e.offset, e.text);
  const auto dot2 = rest.find('.');
  const std::string node_name = rest.substr(0, dot2);
  const std::string what = dot2 == std::string::npos ? "" : rest.substr(dot2 + 1);
  auto* n = find_node(node_name);
  if (!n || n->bus != bus) throw LoadError(e.mark, "signal '" + e.text + "': no node '" + node_name + "' on bus '" + bus_name + "'");
  Signal::Counter c = Signal::Counter::Tec;
  if (what == "tec") c = Signal::Counter::Tec;
  else if (what == "rec") c = Signal::Counter::Rec;
  else if (what == "error_state") c = Signal::Counter::State;
  else throw LoadError(e.mark, "signal '" + e.text + "': a node's bus signal is tec, rec or error_state");
  return Signal::bus_counter(b, n->device->node().endpoint(), c, e.scale, e.offset, e.text);
}

std::vector<SignalExpr> World::wired_signals() const {
  std::vector<SignalExpr> out;
  auto add = [&](const std::string& name, const SourceMark& mark) {
    for (const auto& s : out)
      if (s.text == name) return;
    out.push_back(parse_signal(name, mark));
  };
  for (const auto& w : scenario_.wires) {
    add(w.from, w.from_mark);
    add(w.to, w.to_mark);
  }
  return out;
}

}  // namespace scenario
