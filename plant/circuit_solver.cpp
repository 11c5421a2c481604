#include "plant/circuit_solver.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "plant/component.h"
#include "plant/equations.h"
#include "plant/fluid.h"
#include "plant/rigid_body_world.h"

namespace plant {
namespace {

constexpr double kGamma = 1.0 - 1.0 / std::numbers::sqrt2;
// A body slower than this (m/s or rad/s) counts as at rest: ODE's stiction motor leaves
// residual speeds many orders of magnitude below it.
constexpr double kRestSpeed = 1e-6;
// A slider within this distance (m) of a stop counts as resting on it.
constexpr double kStopTolerance = 1e-9;
// A node within this pressure (Pa) of the cavitation pressure counts as cavitating when drained.
constexpr double kCavitationTolerance = 1.0;
// Step-size control: local error tolerances and how often a step may be halved.
constexpr double kPressureTolerance = 0.5e5;  // Pa
constexpr double kSpeedTolerance = 1e-3;      // m/s or rad/s
constexpr double kRelativeTolerance = 0.01;
constexpr int kMaxHalvings = 6;

}  // namespace

CircuitSolver::CircuitSolver(std::vector<Component*> components, const Fluid& fluid, RigidBodyWorld& world, int nodes,
                             int pressure_states)
    : components_(std::move(components)),
      fluid_(fluid),
      world_(world),
      np_(pressure_states),
      nv_(world.size()),
      n_(pressure_states + world.size()),
      lu_(pressure_states + world.size()) {
  const auto nodes_u = static_cast<std::size_t>(nodes), nv = static_cast<std::size_t>(nv_);
  state_.pressure.assign(nodes_u, 0.0);
  state_.velocity.assign(nv, 0.0);
  state_.position.assign(nv, 0.0);
  for (int b = 0; b < nv_; ++b) state_.position[static_cast<std::size_t>(b)] = world_.position(DofId{b});
  state_.pressure_states = np_;
  state_.fluid = &fluid_;
  stage_ = state_;
  start_pressure_ = state_.pressure;
  volume_.assign(nodes_u, 0.0);
  fixed_volume_.assign(nodes_u, 0.0);
  for (Component* c : components_) {
    if (c->volumes_move()) moving_volumes_.push_back(c);
    if (c->uses(Component::kStamps)) stamping_.push_back(c);
  }
  vapour_.assign(static_cast<std::size_t>(np_), 0.0);
  cavitating_.assign(static_cast<std::size_t>(np_), 0);
  mass_.assign(nv, 0.0);
  inverse_mass_.assign(nv, 0.0);
  dry_static_.assign(nv, 0.0);
  dry_kinetic_.assign(nv, 0.0);
  friction_.assign(nv, 0.0);
  friction_limit_.assign(nv, 0.0);
  ode_force_.assign(nv, 0.0);
  held_.assign(nv, 0);
  const auto n = static_cast<std::size_t>(n_);
  for (std::vector<double>* v : {&r_, &r0_, &f_, &k1_, &k2_, &y_, &scale_}) v->assign(n, 0.0);
  g_.assign(n * n, 0.0);
  pattern_.assign(n * n, 0);
  for (std::size_t i = 0; i < n; ++i) pattern_[i * n + i] = 1;
  refresh();
}

void CircuitSolver::refresh() {
  std::fill(mass_.begin(), mass_.end(), 0.0);
  for (const Component* c : components_) c->add_inertia(mass_);
  for (int b = 0; b < nv_; ++b) world_.set_mass(DofId{b}, mass_[static_cast<std::size_t>(b)]);
  for (std::size_t b = 0; b < mass_.size(); ++b) inverse_mass_[b] = 1.0 / mass_[b];
  // Boundary pressures and the volumes that do not move change only with the parameters.
  for (const Component* c : components_) c->fix_pressures(state_);
  for (std::size_t i = static_cast<std::size_t>(np_); i < state_.pressure.size(); ++i) stage_.pressure[i] = state_.pressure[i];
  std::fill(fixed_volume_.begin(), fixed_volume_.end(), 0.0);
  for (const Component* c : components_)
    if (!c->volumes_move()) c->add_volumes(state_, fixed_volume_);
  volume_ = fixed_volume_;
  for (const Component* c : moving_volumes_) c->add_volumes(state_, volume_);
  air_free_ = fluid_.parameter(Fluid::kAirFraction) <= 0.0;
  beta_liquid_ = fluid_.bulk_modulus(0.0);
  cavitation_pressure_ = fluid_.cavitation_pressure();
  cavitation_beta_ = fluid_.bulk_modulus(cavitation_pressure_);
}

void CircuitSolver::evaluate(const CircuitState& s, Equations::Mode m) {
  std::fill(r_.begin(), r_.end(), 0.0);
  if (m == Equations::Mode::Jacobian) {
    std::fill(g_.begin(), g_.end(), 0.0);
    std::fill(dry_static_.begin(), dry_static_.end(), 0.0);
    std::fill(dry_kinetic_.begin(), dry_kinetic_.end(), 0.0);
  }
  Equations eq(s, m, r_.data(), g_.data(), n_, dry_static_, dry_kinetic_, power_);
  if (m == Equations::Mode::Jacobian) eq.record_pattern(pattern_, pattern_grew_);
  for (const Component* c : stamping_) c->stamp(eq);
  // A coupling seen for the first time (a valve edge opened): the elimination order is chosen
  // anew for the pattern seen so far (rarely; the entries of a closed edge stay in it).
  if (pattern_grew_) {
    lu_.set_pattern(pattern_);
    pattern_grew_ = false;
  }
}

void CircuitSolver::account_power(const CircuitState& s, std::array<double, kEnergyKinds>& power) {
  power.fill(0.0);
  Equations eq(s, Equations::Mode::Power, r_.data(), g_.data(), n_, dry_static_, dry_kinetic_, power);
  for (const Component* c : stamping_) c->stamp(eq);
}

double CircuitSolver::kinetic_energy() const {
  double e = 0.0;
  for (int b = 0; b < nv_; ++b) {
    const auto i = static_cast<std::size_t>(b);
    e += 0.5 * mass_[i] * state_.velocity[i] * state_.velocity[i];
  }
  return e;
}

double CircuitSolver::vapour_volume() const {
  double v = 0.0;
  for (double x : vapour_) v += x;
  return v;
}

void CircuitSolver::set_energy_accounting(bool on) {
  if (on && !accounting_) {
    ledger_ = EnergyLedger{};
    ledger_.kinetic = ledger_.kinetic_start = kinetic_energy();
  }
  accounting_ = on;
}

void CircuitSolver::classify_bodies() {
  for (int b = 0; b < nv_; ++b) {
    const auto bu = static_cast<std::size_t>(b);
    const int row = np_ + b;
    const double v = state_.velocity[bu];
    const double force = r_[row];
    held_[bu] = 0;
    if (std::abs(v) <= kRestSpeed) {
      // At rest: it moves only if the force beats static friction in a direction it may go.
      const double fs = dry_static_[bu];
      bool may_rise = true, may_fall = true;
      if (world_.is_slider(DofId{b})) {
        may_fall = state_.position[bu] > world_.lower(DofId{b}) + kStopTolerance;
        may_rise = state_.position[bu] < world_.upper(DofId{b}) - kStopTolerance;
      }
      if (force > fs && may_rise) {
        friction_[bu] = -fs;
      } else if (force < -fs && may_fall) {
        friction_[bu] = fs;
      } else {
        held_[bu] = 1;
        friction_[bu] = 0.0;
      }
      friction_limit_[bu] = fs;
    } else {
      friction_[bu] = v > 0.0 ? -dry_kinetic_[bu] : dry_kinetic_[bu];
      friction_limit_[bu] = dry_kinetic_[bu];
    }
  }
}

void CircuitSolver::classify_nodes() {
  const double floor = cavitation_pressure_ + kCavitationTolerance;
  const double* const vapour = vapour_.data();
  const double* const pressure = state_.pressure.data();
  const double* const inflow = r_.data();
  std::uint16_t* const cavitating = cavitating_.data();
  for (std::size_t i = 0; i < static_cast<std::size_t>(np_); ++i) {
    // Cavitating: vapour is present, or the node sits at the vapour pressure and is being drained.
    cavitating[i] = vapour[i] > 0.0 || (pressure[i] <= floor && inflow[i] < 0.0);
  }
}

void CircuitSolver::step(double h) { advance(h, 0); }

// One ROS2 step of length h, or - when its error estimate says the step straddled a sharp change
// the Jacobian did not see (a relief valve opening, a port closing) - two half steps, down to
// h / 2^kMaxHalvings. Nothing is changed before the step is accepted.
void CircuitSolver::advance(double h, int depth) {
  // Chamber volumes at the step's midpoint position (predicted), so the position-dependent
  // capacitance does not cost the method its second order.
  for (int b = 0; b < nv_; ++b) {
    const auto bu = static_cast<std::size_t>(b);
    stage_.position[bu] = state_.position[bu] + 0.5 * h * state_.velocity[bu];
  }
  std::copy(fixed_volume_.begin(), fixed_volume_.end(), volume_.begin());
  for (const Component* c : moving_volumes_) c->add_volumes(stage_, volume_);
  if (accounting_) account_power(state_, power_start_);
  if (accounting_) start_pressure_ = state_.pressure;
  const double vapour_before = accounting_ ? vapour_volume() : 0.0;

  // --- f(y) and J at the start of the step; which constraints are active ---
  evaluate(state_, Equations::Mode::Jacobian);
  std::copy(r_.begin(), r_.end(), r0_.begin());
  classify_bodies();
  classify_nodes();
  // W = I - gamma h J, row by row, straight into the LU's storage. Row i of J is scale_i times row
  // i of g (dp/dt = beta/V * inflow, dv/dt = force/m); held bodies and cavitating nodes keep their
  // value (their row of W is the identity's).
  const auto n = static_cast<std::size_t>(n_);
  const double minus_gamma_h = -kGamma * h;
  auto assemble_row = [&](std::size_t row, bool pinned, double diagonal_extra) {
    double* const w = lu_.values();
    const SmallLu::RowSlots slots = lu_.row(row);
    if (pinned) {
      for (const SmallLu::Slot* e = slots.first; e != slots.last; ++e) w[e->flat] = 0.0;
      w[slots.diagonal] = 1.0;
      return;
    }
    const double* g = &g_[row * n];
    const double scale = scale_[row];
    for (const SmallLu::Slot* e = slots.first; e != slots.last; ++e) w[e->flat] = minus_gamma_h * (scale * g[e->column]);
    w[slots.diagonal] = minus_gamma_h * (scale * g[row] + diagonal_extra) + 1.0;
  };
  for (int i = 0; i < np_; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    double slope = 0.0;
    const double beta = air_free_ ? beta_liquid_ : fluid_.bulk_modulus(state_.pressure[iu], &slope);
    scale_[iu] = beta / volume_[iu];
    f_[iu] = cavitating_[iu] ? 0.0 : scale_[iu] * r_[iu];
    // The stiffening of air-laden oil as pressure rises (slope * inflow > 0) is a growing mode;
    // only its damping half belongs in W, or W loses its diagonal dominance at low pressure.
    assemble_row(iu, cavitating_[iu] != 0, slope != 0.0 ? std::min(slope * r_[iu], 0.0) / volume_[iu] : 0.0);
  }
  for (int b = 0; b < nv_; ++b) {
    const auto bu = static_cast<std::size_t>(b);
    const auto row = static_cast<std::size_t>(np_ + b);
    scale_[row] = inverse_mass_[bu];
    f_[row] = held_[bu] ? 0.0 : (r_[row] + friction_[bu]) * scale_[row];
    assemble_row(row, held_[bu] != 0, 0.0);
  }

  // --- ROS2 stages ---
  lu_.factor();
  lu_.solve(f_.data(), k1_.data());

  // y + h k1 (the boundary pressures are stage_'s since refresh())
  for (int i = 0; i < np_; ++i)
    stage_.pressure[static_cast<std::size_t>(i)] = state_.pressure[static_cast<std::size_t>(i)] + h * k1_[i];
  for (int b = 0; b < nv_; ++b) {
    const auto bu = static_cast<std::size_t>(b);
    stage_.position[bu] = state_.position[bu];
    stage_.velocity[bu] = state_.velocity[bu] + h * k1_[np_ + b];
  }
  evaluate(stage_, Equations::Mode::Residual);
  // f(y + h k1) - 2 k1
  for (int i = 0; i < np_; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    double f = 0.0;
    // (beta / V as at the step's start when beta is a constant)
    if (!cavitating_[iu]) f = (air_free_ ? scale_[iu] : fluid_.bulk_modulus(stage_.pressure[iu]) / volume_[iu]) * r_[i];
    f_[i] = f - 2.0 * k1_[i];
  }
  for (int b = 0; b < nv_; ++b) {
    const auto bu = static_cast<std::size_t>(b);
    const int row = np_ + b;
    f_[row] = (held_[bu] ? 0.0 : (r_[row] + friction_[bu]) * scale_[row]) - 2.0 * k1_[row];
  }
  lu_.solve(f_.data(), k2_.data());
  for (std::size_t i = 0; i < n; ++i) y_[i] = (1.5 * h) * k1_[i] + (0.5 * h) * k2_[i];  // increment over the step

  if (depth < kMaxHalvings && error_too_large(h)) {
    advance(0.5 * h, depth + 1);
    advance(0.5 * h, depth + 1);
    return;
  }

  ++steps_taken_;

  // --- Rigid bodies in ODE ---
  if (nv_ > 0) {
    for (int b = 0; b < nv_; ++b) {
      const auto bu = static_cast<std::size_t>(b);
      const int row = np_ + b;
      if (held_[bu]) {
        // The force at the end of the step (linearised); ODE decides whether it breaks away.
        const double* g = &g_[static_cast<std::size_t>(row) * n];
        double dot = g[0] * y_[0];
        for (std::size_t j = 1; j < n; ++j) dot += g[j] * y_[j];
        ode_force_[bu] = r0_[row] + dot;
      } else {
        // The force that gives exactly the predicted velocity change once ODE's motor has
        // applied the dry friction.
        ode_force_[bu] = mass_[bu] * y_[row] / h - friction_[bu];
      }
    }
    world_.step(h, ode_force_, friction_limit_);
  }

  // --- Commit; where ODE's motion differs from the prediction (a stop was hit, the body stuck),
  // the nodes get the volume that was not displaced ---
  for (int i = 0; i < np_; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    state_.pressure[iu] += y_[i];
    // A cavitating node's vapour absorbs its net outflow (mean of the start and stage flows).
    if (cavitating_[iu]) vapour_[iu] -= 0.5 * h * (r0_[i] + r_[i]);
  }
  for (int b = 0; b < nv_; ++b) {
    const auto bu = static_cast<std::size_t>(b);
    const int row = np_ + b;
    const double predicted = state_.velocity[bu] + y_[row];
    const double actual = world_.velocity(DofId{b});
    const double dv = actual - predicted;
    if (dv != 0.0) {
      for (int i = 0; i < np_; ++i) {
        const auto iu = static_cast<std::size_t>(i);
        const double j_node_body = scale_[iu] * g_[iu * n + static_cast<std::size_t>(row)];  // dp_i/dt per v
        const double dp = h * j_node_body * dv;
        if (cavitating_[iu]) {
          vapour_[iu] -= dp / scale_[i];
        } else {
          state_.pressure[iu] += dp;
        }
      }
    }
    state_.velocity[bu] = actual;
    state_.position[bu] = world_.position(DofId{b});
  }
  if (accounting_) {
    for (int i = 0; i < np_; ++i) {
      const auto iu = static_cast<std::size_t>(i);
      ledger_.fluid_stored += compression_energy(volume_[iu], start_pressure_[iu], state_.pressure[iu]);
    }
  }
  settle_vapour();

  if (accounting_) {
    account_power(state_, power_end_);
    for (std::size_t k = 0; k < power_end_.size(); ++k)
      ledger_.by_kind[k] += 0.5 * h * (power_start_[k] + power_end_[k]);
    // Vapour grows at the cavitation pressure p_cav: the fluid does work p_cav * dV on it.
    ledger_.by_kind[static_cast<std::size_t>(EnergyKind::Cavitation)] -=
        fluid_.cavitation_pressure() * (vapour_volume() - vapour_before);
    for (int b = 0; b < nv_; ++b) {
      ledger_.dry_friction += world_.friction_loss(DofId{b});
      ledger_.end_stops += world_.impact_loss(DofId{b});
    }
    ledger_.kinetic = kinetic_energy();
  }
}

// After a step: vapour that the inflow has refilled collapses (the surplus compresses the liquid),
// and a node that the step took below the cavitation pressure is brought back to it, the
// shortfall becoming vapour. Both keep the fluid volume balance exact.
void CircuitSolver::settle_vapour() {
  const double p_cav = cavitation_pressure_;
  const double beta_cav = cavitation_beta_;
  for (int i = 0; i < np_; ++i) {
    const auto iu = static_cast<std::size_t>(i);
    double& p = state_.pressure[iu];
    const double before = p;
    if (cavitating_[iu]) {
      p = p_cav;
      if (vapour_[iu] < 0.0) {
        p = p_cav - vapour_[iu] * beta_cav / volume_[iu];
        vapour_[iu] = 0.0;
      }
    } else if (p < p_cav) {
      vapour_[iu] = (p_cav - p) * volume_[iu] / beta_cav;
      p = p_cav;
    }
    if (accounting_ && p != before) ledger_.fluid_stored += compression_energy(volume_[iu], before, p);
  }
}

// The embedded first-order solution of ROS2 is y + h k1; the difference to the second-order one,
// h/2 (k1 + k2), estimates the error. Weighted per state: pressures to 0.5 bar + 1 %, speeds to
// 1 mm/s (or mrad/s) + 1 %; pinned states (held bodies, cavitating nodes) do not count. True when
// any state's estimate exceeds its tolerance.
bool CircuitSolver::error_too_large(double h) const {
  const auto np = static_cast<std::size_t>(np_), nv = static_cast<std::size_t>(nv_);
  const double* const k1 = k1_.data();
  const double* const k2 = k2_.data();
  const double* const pressure = state_.pressure.data();
  const double* const velocity = state_.velocity.data();
  const double half_h = 0.5 * h;
  bool too_large = false;  // (no early exit: almost every step is accepted)
  for (std::size_t i = 0; i < np; ++i) {
    const double tolerance = kPressureTolerance + kRelativeTolerance * std::abs(pressure[i]);
    too_large |= !cavitating_[i] && std::abs(half_h * (k1[i] + k2[i])) > tolerance;
  }
  for (std::size_t b = 0; b < nv; ++b) {
    const double tolerance = kSpeedTolerance + kRelativeTolerance * std::abs(velocity[b]);
    too_large |= !held_[b] && std::abs(half_h * (k1[np + b] + k2[np + b])) > tolerance;
  }
  return too_large;
}

double CircuitSolver::compression_energy(double volume, double p0, double p1) const {
  // integral of p V / beta(p) dp, trapezoidal
  return 0.5 * volume * (p0 / fluid_.bulk_modulus(p0) + p1 / fluid_.bulk_modulus(p1)) * (p1 - p0);
}

}  // namespace plant
