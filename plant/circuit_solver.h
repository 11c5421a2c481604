// Integrates the circuit over one physics step: node pressures and body velocities implicitly
// (they are stiff: a cylinder chamber's pressure settles in microseconds), body positions in ODE.
//
// Method: ROS2, the two-stage L-stable Rosenbrock method of Verwer, Spee, Blom and Hundsdorfer
// (SIAM J. Sci. Comput. 20, 1999):
//     W = I - gamma h J,   W k1 = f(y),   W k2 = f(y + h k1) - 2 k1,   y' = y + h (3/2 k1 + 1/2 k2)
// Second order and L-stable for gamma = 1 +- 1/sqrt(2) (stiff modes are damped, not rung); one LU
// of W per step; second order even with an inexact Jacobian (a W-method), which keeps it robust at
// the models' kinks. We take gamma = 1 - 1/sqrt(2): still A- and L-stable (gamma >= 1/4), and far
// more accurate on the lightly damped mass-on-oil-spring oscillations (at w h = 0.34 its phase
// error is -0.5 % and amplitude loss 0.005 % per step, against +7 % and 3.4 % for 1 + 1/sqrt(2)).
// y = [node pressures; body velocities], f = [beta(p)/V * net inflow; net force / mass]. Steps
// whose embedded error estimate is too large are halved (see advance()).
//
// Coupling to ODE: the solver predicts the step's end velocities, hands ODE the force that
// produces exactly that change (plus the dry friction, which ODE applies itself as a
// force-limited joint motor), and lets ODE integrate positions, hold stiction and enforce end
// stops. Where ODE's velocity differs (a stop was hit, the body stuck) the pressures are corrected
// for the volume that was not displaced. Bodies at rest whose force cannot overcome static
// friction or an end stop are held at zero velocity in the solve, so both sides agree.
#pragma once

#include <cstdint>
#include <vector>

#include "plant/circuit_state.h"
#include "plant/energy_ledger.h"
#include "plant/equations.h"
#include "plant/small_lu.h"

namespace plant {

class Component;
class Fluid;
class RigidBodyWorld;

class CircuitSolver {
 public:
  /// nodes: all pressure nodes, of which the first `pressure_states` are integrated.
  CircuitSolver(std::vector<Component*> components, const Fluid& fluid, RigidBodyWorld& world, int nodes,
                int pressure_states);

  CircuitState& state() { return state_; }
  const CircuitState& state() const { return state_; }

  /// Recomputes body masses and boundary pressures (after construction or a parameter change).
  void refresh();
  /// Advances pressures, velocities and positions by h (components have advanced already).
  void step(double h);

  /// Physics steps taken, counting the halves of steps the error control split.
  std::uint64_t steps_taken() const { return steps_taken_; }

  void set_energy_accounting(bool on);
  const EnergyLedger& energy() const { return ledger_; }

 private:
  void evaluate(const CircuitState& s, Equations::Mode mode);
  void account_power(const CircuitState& s, std::array<double, kEnergyKinds>& power);
  void advance(double h, int depth);
  bool error_too_large(double h) const;
  void classify_bodies();
  void classify_nodes();
  void settle_vapour();
  double kinetic_energy() const;
  double vapour_volume() const;
  /// Energy to compress `volume` of fluid from p0 to p1: integral of p V/beta(p) dp (trapezoid).
  double compression_energy(double volume, double p0, double p1) const;

  std::vector<Component*> components_;
  std::vector<Component*> moving_volumes_;  // the components whose volumes follow body positions
  std::vector<Component*> stamping_;        // the components that stamp (Component::uses())
  const Fluid& fluid_;
  RigidBodyWorld& world_;
  int np_;  // pressure states
  int nv_;  // bodies
  int n_;   // np_ + nv_

  CircuitState state_;
  CircuitState stage_;
  std::vector<double> volume_;          // per node, m^3
  std::vector<double> fixed_volume_;    // per node: the part that does not follow body positions, m^3
  bool air_free_ = false;               // the fluid's bulk modulus is a constant, beta_liquid_
  double beta_liquid_ = 0.0;
  double cavitation_pressure_ = 0.0;    // the fluid's, and its bulk modulus there (from refresh())
  double cavitation_beta_ = 0.0;
  std::vector<double> vapour_;          // per pressure state: vapour volume of a cavitating node, m^3
  // Flags as uint16_t, not char: a store through a char type may alias anything, and would make
  // the compiler reload every vector's data pointer in the loops that set them.
  std::vector<std::uint16_t> cavitating_;  // per pressure state, this step
  std::vector<double> start_pressure_;  // pressures at the start of the step
  std::vector<double> mass_;    // per body
  std::vector<double> inverse_mass_;
  std::vector<double> dry_static_, dry_kinetic_;
  std::vector<double> friction_;        // dry friction force used in the solve, per body
  std::vector<double> friction_limit_;  // force limit handed to ODE, per body
  std::vector<double> ode_force_;
  std::vector<std::uint16_t> held_;
  std::array<double, kEnergyKinds> power_{};  // scratch for Residual/Jacobian modes
  std::array<double, kEnergyKinds> power_start_{}, power_end_{};

  // Per unknown (pressure states, then bodies), allocated once. The system is small and sparse:
  // plain loops over row-major storage, W assembled straight into the LU's storage.
  std::vector<double> r_, r0_, f_, k1_, k2_, y_, scale_;
  std::vector<double> g_;  // n x n row-major: d(residual)/d(state) of the last Jacobian evaluation
  std::vector<std::uint16_t> pattern_;  // n x n: the entries of g (and so of W) any stamp has written so far
  bool pattern_grew_ = false;
  SmallLu lu_;             // holds W = I - gamma h J, then its factors

  std::uint64_t steps_taken_ = 0;
  bool accounting_ = false;
  EnergyLedger ledger_;
};

}  // namespace plant
