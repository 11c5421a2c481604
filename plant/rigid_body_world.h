// The rigid bodies of the machine in ODE: each mechanical degree of freedom is one body on one
// joint to the fixed world - a cylinder rod and its load on a slider joint with hard end stops, a
// shaft on a hinge joint. ODE integrates their motion under the forces the circuit solver computes,
// enforces the end stops, and applies dry friction as a joint motor with a force limit (target
// speed 0), which gives exact stiction: a body stays at rest until the force exceeds the limit.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "plant/circuit_state.h"

struct dxWorld;

namespace plant {

class RigidBodyWorld {
 public:
  RigidBodyWorld();
  ~RigidBodyWorld();
  RigidBodyWorld(const RigidBodyWorld&) = delete;
  RigidBodyWorld& operator=(const RigidBodyWorld&) = delete;

  /// A translational body on a slider along its axis, with end stops at lower/upper (m).
  DofId add_slider(double lower, double upper, double initial_position);
  /// A rotational body on a hinge; its angle counts on over any number of turns.
  DofId add_hinge(double initial_angle);

  void set_mass(DofId dof, double mass);  ///< kg (slider) or kg m^2 about the axis (hinge)
  void set_limits(DofId dof, double lower, double upper);
  int size() const { return static_cast<int>(dofs_.size()); }

  bool is_slider(DofId dof) const;
  double lower(DofId dof) const;
  double upper(DofId dof) const;

  /// Sizes ODE's step memory for all bodies, so that no step allocates (once, after the bodies are
  /// added; bodies at rest stay where they are).
  void reserve_step_memory();

  /// One step of length h: force[i] (N or N m) along each body's axis; friction_limit[i] >= 0 is
  /// the dry friction the body's joint motor may apply to hold it at rest or brake it.
  void step(double h, std::span<const double> force, std::span<const double> friction_limit);

  double position(DofId dof) const;  ///< m within the stops, or unbounded rad
  double velocity(DofId dof) const;  ///< m/s or rad/s
  /// Energy dissipated in the last step by the joint motor (dry friction) (J, >= 0).
  double friction_loss(DofId dof) const;
  /// Kinetic energy lost in the last step by an inelastic impact on an end stop (J).
  double impact_loss(DofId dof) const;
  /// Steps in which ODE stepped at least one body (the others were sliding freely).
  std::uint64_t ode_steps() const { return ode_steps_; }

 private:
  struct Dof;
  Dof& at(DofId dof) const;
  /// Writes the motion integrated in closed form since the body's last ODE step into ODE.
  static void hand_to_ode(Dof& d);

  dxWorld* world_;
  std::vector<std::unique_ptr<Dof>> dofs_;
  std::uint64_t ode_steps_ = 0;
};

}  // namespace plant
