// The plant: a circuit of components built from a PlantDescription, advanced by the scheduler
// as one Steppable. Each step(now, dt) reads the input ports, advances the physics by exactly dt
// in equal sub-steps no longer than the description's max_step, and refreshes the output ports.
// Deterministic: the same description and inputs give bit-identical outputs.
//
// Ports are named "<component>.<signal>" (e.g. "cyl.position", "valve_cyl.solenoid_a_current")
// and point at doubles owned by the plant for its whole life. Inputs hold their last value when
// nothing writes them. Parameters are addressed the same way ("relief.cracking_pressure") and may
// be changed between steps for fault injection.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "plant/diagnostic.h"
#include "plant/energy_ledger.h"
#include "plant/plant_description.h"
#include "sim/ports.h"
#include "sim/scheduler.h"

namespace plant {

class CircuitSolver;
class Component;
class RigidBodyWorld;

class Plant final : public sim::Steppable {
 public:
  /// Throws DescriptionError when the description is not a buildable plant.
  explicit Plant(const PlantDescription& description);
  ~Plant() override;
  Plant(const Plant&) = delete;
  Plant& operator=(const Plant&) = delete;

  void step(sim::Time now, sim::Duration dt) override;

  /// All signal ports of all components; the value pointers stay valid for the plant's life.
  const sim::PortList& ports() const { return ports_; }
  /// The value behind a port name, or nullptr.
  double* port(std::string_view qualified_name) const;

  /// "component.parameter" = value, checked like a description (range, consistency).
  Status set_parameter(std::string_view qualified_name, double value);
  std::optional<double> parameter(std::string_view qualified_name) const;
  /// Every "component.parameter" set_parameter() knows, in component order.
  std::vector<std::string> parameter_names() const;

  /// Energy bookkeeping (costs two extra evaluations per physics step; off by default).
  void set_energy_accounting(bool on);
  const EnergyLedger& energy() const;

  double physics_step() const { return h_; }  ///< s, nominal, of the last tick
  /// Physics steps since construction, including those the error control split into halves.
  std::uint64_t physics_steps() const;
  /// Physics steps in which ODE stepped a body (one stuck, held or on a stop; rigid_body_world.h).
  std::uint64_t ode_steps() const;

 private:
  Component* find(std::string_view name) const;

  std::unique_ptr<RigidBodyWorld> world_;
  std::vector<std::unique_ptr<Component>> components_;
  // The components whose per-step hooks do something (Component::uses()).
  std::vector<Component*> reading_, advancing_, publishing_;
  std::unique_ptr<CircuitSolver> solver_;
  sim::PortList ports_;
  double max_step_;
  double h_ = 0.0;
  int substeps_ = 0;
  sim::Duration configured_for_{0};
};

}  // namespace plant
