// The interface through which a component states its physics to the circuit solver, in the manner
// of circuit simulators' "stamps": a flow between two nodes, a volume displaced by a moving body,
// a force on a body. The same call serves three purposes depending on the mode:
//   Residual  - accumulate net inflow per node and net force per body,
//   Jacobian  - also accumulate their derivatives (for the implicit step) and dry friction levels,
//   Power     - accumulate the power each flow or force dissipates, by EnergyKind.
// So a model's equations are written once and the energy balance cannot drift from them.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "plant/circuit_state.h"

namespace plant {

class Equations {
 public:
  enum class Mode { Residual, Jacobian, Power };

  /// residual: one entry per unknown (pressure states, then bodies); jacobian: row-major, `unknowns`
  /// entries per row (the solver's storage, used in place).
  Equations(const CircuitState& state, Mode mode, double* residual, double* jacobian, int unknowns,
            std::vector<double>& dry_static, std::vector<double>& dry_kinetic, std::array<double, kEnergyKinds>& power)
      : s_(state), mode_(mode), r_(residual), g_(jacobian), n_(static_cast<std::size_t>(unknowns)),
        dry_static_(dry_static), dry_kinetic_(dry_kinetic), power_(power) {}

  /// Jacobian mode needs this: each entry of the Jacobian a stamp writes is marked in `pattern`
  /// (row-major, like the Jacobian), and `grew` set when one was not marked before.
  void record_pattern(std::vector<std::uint16_t>& pattern, bool& grew) {
    pattern_ = pattern.data();
    grew_ = &grew;
  }

  Mode mode() const { return mode_; }
  bool wants_jacobian() const { return mode_ == Mode::Jacobian; }

  const Fluid& fluid() const { return *s_.fluid; }
  double pressure(NodeId n) const { return s_.p(n); }
  double velocity(DofId d) const { return s_.v(d); }
  double position(DofId d) const { return s_.x(d); }

  /// Flow q (m^3/s) from node `from` to node `to`; dq_ddp = dq/d(p_from - p_to).
  [[gnu::always_inline]] void flow(NodeId from, NodeId to, double q, double dq_ddp, EnergyKind kind) {
    if (mode_ == Mode::Power) {
      if (kind != EnergyKind::Internal) power_[static_cast<int>(kind)] += (s_.p(from) - s_.p(to)) * q;
      return;
    }
    const bool fs = is_state(from), ts = is_state(to);
    if (fs) r_[from.index] -= q;
    if (ts) r_[to.index] += q;
    if (mode_ == Mode::Jacobian) {
      if (fs) {
        diagonal(from.index) -= dq_ddp;
        if (ts) g(from.index, to.index) += dq_ddp;
      }
      if (ts) {
        diagonal(to.index) -= dq_ddp;
        if (fs) g(to.index, from.index) += dq_ddp;
      }
    }
  }

  /// A body that changes the volume of `node` by `area` per unit of its coordinate (m^2, or
  /// m^3/rad for a motor): the node loses area*v of inflow and the body feels area*p.
  [[gnu::always_inline]] void displacement(NodeId node, DofId dof, double area) {
    if (mode_ == Mode::Power) return;  // conversion between fluid and mechanics, not a loss
    const int row = dof_row(dof);
    const bool ns = is_state(node);
    if (ns) r_[node.index] -= area * s_.v(dof);
    r_[row] += area * s_.p(node);
    if (mode_ == Mode::Jacobian) {
      if (ns) {
        g(node.index, row) -= area;
        g(row, node.index) += area;
      }
    }
  }

  /// Force (or torque) f on a body that depends on pressures only through stamps above;
  /// df_dv = df/dv of the same body.
  [[gnu::always_inline]] void force(DofId dof, double f, double df_dv, EnergyKind kind) {
    if (mode_ == Mode::Power) {
      if (kind != EnergyKind::Internal) power_[static_cast<int>(kind)] -= f * s_.v(dof);
      return;
    }
    const int row = dof_row(dof);
    r_[row] += f;
    if (mode_ == Mode::Jacobian) diagonal(row) += df_dv;
  }

  /// Dry (Coulomb/Stribeck) friction on a body: the levels it can hold at rest and while sliding.
  /// ODE applies it as a joint motor with a force limit, so stiction is exact; only recorded in
  /// Jacobian mode (once per step, at the state the step starts from).
  void dry_friction(DofId dof, double static_level, double kinetic_level) {
    if (mode_ != Mode::Jacobian) return;
    dry_static_[static_cast<std::size_t>(dof.index)] += static_level;
    dry_kinetic_[static_cast<std::size_t>(dof.index)] += kinetic_level;
  }

 private:
  bool is_state(NodeId n) const { return n.index < s_.pressure_states; }
  int dof_row(DofId d) const { return s_.pressure_states + d.index; }

  const CircuitState& s_;
  Mode mode_;
  double& g(int row, int column) {
    const std::size_t i = static_cast<std::size_t>(row) * n_ + static_cast<std::size_t>(column);
    // Marked in place (no call, and not through a char type, which may alias anything): the
    // compiler keeps the stamps' other values in registers across it.
    if (pattern_[i] == 0) [[unlikely]] {
      pattern_[i] = 1;
      *grew_ = true;
    }
    return g_[i];
  }
  // The diagonal is in the pattern from the start (the solver marks it), so needs no check.
  double& diagonal(int row) { return g_[static_cast<std::size_t>(row) * (n_ + 1)]; }

  double* r_;
  double* g_;
  std::size_t n_;
  std::vector<double>& dry_static_;
  std::vector<double>& dry_kinetic_;
  std::array<double, kEnergyKinds>& power_;
  std::uint16_t* pattern_ = nullptr;
  bool* grew_ = nullptr;
};

}  // namespace plant
