// A shaft with a flywheel: a rigid body on an ODE hinge joint with inertia, viscous and dry
// (Coulomb) bearing friction and a load torque. Motors couple to it through its `flange`. Its
// angle is unbounded: it keeps counting over any number of turns, as a multiturn encoder needs.
#pragma once

#include "plant/component.h"

namespace plant {

class RotaryShaft final : public Component {
 public:
  enum Param { kInertia, kViscousFriction, kCoulombFriction, kLoadTorque, kInitialAngle, kParamCount };
  enum Connector { kFlange };
  enum Signal { kAngle, kSpeed, kSignalCount };
  static const ComponentType& type_info();

  RotaryShaft(std::string name, std::vector<double> values);

  void create_bodies(RigidBodyWorld& world) override;
  DofId body(int connector) const override { return connector == kFlange ? shaft_ : DofId{}; }
  void add_inertia(std::vector<double>& dof_mass) const override;
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;

 private:
  DofId shaft_;
};

}  // namespace plant
