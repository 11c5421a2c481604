#include "plant/plant.h"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "plant/circuit_solver.h"
#include "plant/component.h"
#include "plant/fluid.h"
#include "plant/rigid_body_world.h"
#include "sim/tick_profile.h"

namespace plant {
namespace {

[[noreturn]] void fail(const SourceMark& mark, std::string reason) {
  throw DescriptionError(Diagnostic{mark, std::move(reason)});
}

std::pair<std::string_view, std::string_view> split_qualified(std::string_view name) {
  const auto dot = name.find('.');
  if (dot == std::string_view::npos) return {name, {}};
  return {name.substr(0, dot), name.substr(dot + 1)};
}

}  // namespace

Plant::Plant(const PlantDescription& description) : max_step_(description.solver.max_step) {
  validate(description);
  world_ = std::make_unique<RigidBodyWorld>();

  std::map<std::string, Component*, std::less<>> by_name;
  const Fluid* fluid = nullptr;
  for (const auto& c : description.components) {
    const ComponentType* type = find_component_type(c.type);
    components_.push_back(type->create(c.name, resolved_parameters(c)));
    Component* component = components_.back().get();
    by_name.emplace(c.name, component);
    if (auto* f = dynamic_cast<const Fluid*>(component)) fluid = f;
  }
  for (auto& c : components_) c->create_bodies(*world_);

  // Nodes: fluid connections without a tank are integrated (indices first), those with a tank
  // are fixed-pressure boundaries (indices after).
  auto is_boundary = [&](const ConnectionDescription& conn) {
    for (const auto& ref : conn.ports)
      if (by_name.at(ref.component)->type().name == "tank") return true;
    return false;
  };
  auto domain_of = [&](const PortReference& ref) {
    const Component* c = by_name.at(ref.component);
    return c->type().connectors[static_cast<std::size_t>(c->type().connector_index(ref.connector))].domain;
  };
  int states = 0, nodes = 0;
  for (const auto& conn : description.connections)
    if (domain_of(conn.ports.front()) == Domain::Fluid && !is_boundary(conn)) ++states;
  int next_state = 0, next_boundary = states;
  std::vector<const ConnectionDescription*> state_connection;
  for (const auto& conn : description.connections) {
    if (domain_of(conn.ports.front()) == Domain::Fluid) {
      const bool boundary = is_boundary(conn);
      const int index = boundary ? next_boundary++ : next_state++;
      if (!boundary) state_connection.push_back(&conn);
      for (const auto& ref : conn.ports) {
        Component* c = by_name.at(ref.component);
        c->connect(c->type().connector_index(ref.connector), index);
      }
      ++nodes;
    } else {
      DofId body;
      for (const auto& ref : conn.ports) {
        const Component* c = by_name.at(ref.component);
        const int index = c->type().connector_index(ref.connector);
        if (c->type().connectors[static_cast<std::size_t>(index)].owns_body) body = c->body(index);
      }
      for (const auto& ref : conn.ports) {
        Component* c = by_name.at(ref.component);
        c->connect(c->type().connector_index(ref.connector), body.index);
      }
    }
  }

  std::vector<Component*> raw;
  for (auto& c : components_) raw.push_back(c.get());
  for (Component* c : raw) {
    if (c->uses(Component::kReadsInputs)) reading_.push_back(c);
    if (c->uses(Component::kAdvances)) advancing_.push_back(c);
    if (c->uses(Component::kPublishes)) publishing_.push_back(c);
  }
  solver_ = std::make_unique<CircuitSolver>(std::move(raw), *fluid, *world_, nodes, states);
  CircuitState& state = solver_->state();
  for (int i = 0; i < states; ++i) state.pressure[static_cast<std::size_t>(i)] = state_connection[static_cast<std::size_t>(i)]->initial_pressure;

  // A node the solver integrates needs a volume (dp/dt = beta/V ...): a hose, a chamber.
  std::vector<double> volume(static_cast<std::size_t>(nodes), 0.0);
  for (const auto& c : components_) c->add_volumes(state, volume);
  for (int i = 0; i < states; ++i) {
    if (!(volume[static_cast<std::size_t>(i)] > 0.0)) {
      const auto* conn = state_connection[static_cast<std::size_t>(i)];
      fail(conn->mark, fmt::format("connection '{}' has no fluid volume: add a 'volume' component (hose, pipe) "
                                   "or a tank to it",
                                   conn->name));
    }
  }
  solver_->refresh();
  world_->reserve_step_memory();

  for (auto& c : components_) {
    const auto& signals = c->type().signals;
    for (std::size_t i = 0; i < signals.size(); ++i) {
      const auto& s = signals[i];
      ports_.push_back(sim::Port{fmt::format("{}.{}", c->name(), s.name), s.direction, std::string(s.unit),
                                 c->signal(i), std::string(s.description), s.display});
    }
  }
  for (auto& c : components_) c->publish(state, 0.0);
}

Plant::~Plant() = default;

void Plant::step(sim::Time /*now*/, sim::Duration dt) {
  if (dt.count() <= 0) return;
  const sim::TickProbe probe(sim::TickPart::Plant);
  const double tick = sim::seconds(dt);
  if (dt != configured_for_) {
    substeps_ = std::max(1, static_cast<int>(std::ceil(tick / max_step_ - 1e-9)));
    h_ = tick / substeps_;
    for (auto& c : components_) c->configure_step(h_);
    configured_for_ = dt;
  }
  for (Component* c : reading_) c->read_inputs();
  for (int s = 0; s < substeps_; ++s) {
    for (Component* c : advancing_) c->advance(h_);
    solver_->step(h_);
  }
  for (Component* c : publishing_) c->publish(solver_->state(), tick);
}

Component* Plant::find(std::string_view name) const {
  for (const auto& c : components_)
    if (c->name() == name) return c.get();
  return nullptr;
}

double* Plant::port(std::string_view qualified_name) const {
  const sim::Port* p = sim::find_port(ports_, qualified_name);
  return p != nullptr ? p->value : nullptr;
}

Status Plant::set_parameter(std::string_view qualified_name, double value) {
  auto [component, parameter] = split_qualified(qualified_name);
  Component* c = find(component);
  if (c == nullptr) return Status::failure(fmt::format("no component named '{}' (in '{}')", component, qualified_name));
  Status status = c->set_parameter(parameter, value);
  if (status) solver_->refresh();
  return status;
}

std::optional<double> Plant::parameter(std::string_view qualified_name) const {
  auto [component, parameter] = split_qualified(qualified_name);
  const Component* c = find(component);
  if (c == nullptr) return std::nullopt;
  const int index = c->type().parameter_index(parameter);
  if (index < 0) return std::nullopt;
  return c->parameter(index);
}

std::vector<std::string> Plant::parameter_names() const {
  std::vector<std::string> names;
  for (const auto& c : components_)
    for (const auto& p : c->type().parameters) names.push_back(c->name() + "." + std::string(p.name));
  return names;
}

std::uint64_t Plant::physics_steps() const { return solver_->steps_taken(); }
std::uint64_t Plant::ode_steps() const { return world_->ode_steps(); }

void Plant::set_energy_accounting(bool on) { solver_->set_energy_accounting(on); }
const EnergyLedger& Plant::energy() const { return solver_->energy(); }

}  // namespace plant
