// A differential (single-rod, double-acting) cylinder with its rod and load as one rigid body on an
// ODE slider joint with hard end stops at 0 (fully retracted) and the stroke.
//
// Chambers: V_A = V_dead,A + A_A x,  V_B = V_dead,B + A_B (stroke - x), A_A = pi/4 D^2,
// A_B = A_A - pi/4 d^2; they join the nodes of ports A and B (dV/dt enters dp/dt = beta/V (Q - dV/dt)).
// Force on the rod (positive = extending): A_A p_A - A_B p_B - c_v v - load_force - F_dry, where the
// dry friction follows a Stribeck curve F_dry(v) = F_c + (F_s - F_c) exp(-(v/v_s)^2) and holds the
// rod at rest up to the static level (applied in ODE). Internal leakage A->B: Q = C_leak (p_A - p_B).
#pragma once

#include "plant/component.h"

namespace plant {

class DifferentialCylinder final : public Component {
 public:
  enum Param {
    kBoreDiameter,
    kRodDiameter,
    kStroke,
    kDeadVolumeA,
    kDeadVolumeB,
    kMass,
    kCoulombFriction,
    kStaticFriction,
    kStribeckVelocity,
    kViscousFriction,
    kLeakageCoefficient,
    kLoadForce,
    kInitialPosition,
    kSensorOffset,
    kParamCount
  };
  enum Connector { kA, kB };
  enum Signal { kPosition, kVelocity, kPressureA, kPressureB, kMagnetPosition, kHydraulicForce, kSignalCount };
  static const ComponentType& type_info();

  DifferentialCylinder(std::string name, std::vector<double> values);

  void create_bodies(RigidBodyWorld& world) override;
  void add_volumes(const CircuitState& state, std::vector<double>& node_volume) const override;
  bool volumes_move() const override { return true; }
  void add_inertia(std::vector<double>& dof_mass) const override;
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;

 private:
  void parameters_changed() override;

  double area_a_ = 0.0;
  double area_b_ = 0.0;
  DofId rod_;
  RigidBodyWorld* world_ = nullptr;
};

}  // namespace plant
