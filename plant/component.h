// Base of every plant component. A component owns its parameters (values checked against its
// type's table), its signal ports (doubles a scenario wires to devices) and its internal states
// (spool positions, swivel angle). It meets the rest of the circuit only through connectors that
// the plant resolves to pressure nodes and rigid bodies; it never knows who is connected.
#pragma once

#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "plant/circuit_state.h"
#include "plant/component_type.h"
#include "plant/diagnostic.h"

namespace plant {

class Equations;
class RigidBodyWorld;

class Component {
 public:
  Component(const ComponentType& type, std::string name, std::vector<double> values);
  virtual ~Component() = default;
  Component(const Component&) = delete;
  Component& operator=(const Component&) = delete;

  const ComponentType& type() const { return type_; }
  const std::string& name() const { return name_; }
  double parameter(int index) const { return values_[static_cast<std::size_t>(index)]; }
  std::span<const double> parameters() const { return values_; }

  /// Changes one parameter at run time (fault injection, load change); refused when out of
  /// range or inconsistent with the others, in which case nothing changes.
  Status set_parameter(std::string_view parameter, double value);

  /// Signal port values, in the order of type().signals; the addresses are stable.
  double* signal(std::size_t index) { return &signals_[index]; }

  // --- Building the circuit (called once by the plant) ---
  /// Binds connector `connector` to a node index (fluid) or a body index (rotational).
  void connect(int connector, int target) { targets_[static_cast<std::size_t>(connector)] = target; }
  /// Components that own rigid bodies create them here (ODE bodies and joints).
  virtual void create_bodies(RigidBodyWorld& /*world*/) {}
  /// For a rotational connector that owns a body: which body it is.
  virtual DofId body(int /*connector*/) const { return {}; }

  // --- Stepping (called by the plant, in this order) ---
  /// The per-step calls below that a component implements: the plant makes only those (a dozen
  /// empty virtual calls per step add up at thousands of steps per second). All, unless a
  /// derived constructor says fewer with declare_hooks().
  enum Hook : unsigned { kReadsInputs = 1u, kAdvances = 2u, kStamps = 4u, kPublishes = 8u };
  bool uses(Hook hook) const { return (hooks_ & hook) != 0; }

  /// Once per tick: copy input ports into internal commands (inputs hold their last value).
  virtual void read_inputs() {}
  /// When the physics step size h is first known or changes: exact discretisations.
  virtual void configure_step(double /*h*/) {}
  /// Once per physics step, before the circuit solve: advance internal linear dynamics (spools,
  /// swash plate) over [t, t+h] and hold the values the circuit uses during the step.
  virtual void advance(double /*h*/) {}
  /// Fixed-pressure boundaries (tanks) write their pressure.
  virtual void fix_pressures(CircuitState& /*state*/) const {}
  /// Volumes this component adds to its nodes (m^3) at the current body positions.
  virtual void add_volumes(const CircuitState& /*state*/, std::vector<double>& /*node_volume*/) const {}
  /// Whether those volumes change with body positions (a cylinder's chambers): then add_volumes()
  /// is called every physics step, else only when the parameters change.
  virtual bool volumes_move() const { return false; }
  /// Mass (kg) or inertia (kg m^2) this component adds to bodies.
  virtual void add_inertia(std::vector<double>& /*dof_mass*/) const {}
  /// The component's flows and forces at the state the Equations expose.
  virtual void stamp(Equations& /*eq*/) const {}
  /// After each tick: refresh output ports from the state; dt is the tick length.
  virtual void publish(const CircuitState& /*state*/, double /*dt*/) {}

 protected:
  NodeId node(int connector) const { return NodeId{targets_[static_cast<std::size_t>(connector)]}; }
  DofId dof(int connector) const { return DofId{targets_[static_cast<std::size_t>(connector)]}; }
  double& out(int signal) { return signals_[static_cast<std::size_t>(signal)]; }
  double in(int signal) const { return signals_[static_cast<std::size_t>(signal)]; }
  /// Called by set_parameter() after every accepted change (and by each derived constructor):
  /// recompute derived quantities.
  virtual void parameters_changed() {}
  /// Declares the per-step hooks this component implements (a mask of Hook); a hook left out is
  /// never called.
  void declare_hooks(unsigned hooks) { hooks_ = hooks; }

 private:
  const ComponentType& type_;
  std::string name_;
  std::vector<double> values_;
  std::vector<double> signals_;
  std::vector<int> targets_;
  unsigned hooks_ = kReadsInputs | kAdvances | kStamps | kPublishes;
};

/// The factory a ComponentType points at: `ComponentType{..., make_component<Tank>}`.
template <typename T>
std::unique_ptr<Component> make_component(std::string name, std::vector<double> values) {
  return std::make_unique<T>(std::move(name), std::move(values));
}

/// Reads a current, command or other device-written input: non-finite values count as 0, since a
/// device that writes NaN must not poison the physics.
inline double sanitize_input(double value) { return std::isfinite(value) ? value : 0.0; }

}  // namespace plant
