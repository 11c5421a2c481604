// Where the energy of a run went: what the sources delivered, what each loss mechanism
// dissipated, what is stored in compressed fluid and moving bodies. Kept by the circuit solver
// when enabled; each term is integrated from its own physical expression, so the balance
//     supplied = losses + delta(fluid) + delta(kinetic)
// is a check on the integration, not an identity.
#pragma once

#include <array>

#include "plant/circuit_state.h"

namespace plant {

struct EnergyLedger {
  /// Energy (J) per EnergyKind from the components' flows and forces: the power each dissipates,
  /// integrated over time. Supply is negative (sources deliver), the others positive.
  std::array<double, kEnergyKinds> by_kind{};
  double dry_friction = 0.0;  ///< J dissipated by joint-motor friction in ODE (Coulomb, Stribeck, motor mech. loss)
  double end_stops = 0.0;     ///< J lost in inelastic impacts on end stops
  double fluid_stored = 0.0;  ///< J stored by compressing fluid since the start: sum of integral p V/beta dp
  double kinetic = 0.0;       ///< J, current kinetic energy of all bodies
  double kinetic_start = 0.0; ///< J, at the start of accounting

  double of(EnergyKind k) const { return by_kind[static_cast<std::size_t>(k)]; }
  /// Hydraulic energy the pumps and flow sources delivered into the circuit (after pump leakage).
  double delivered() const { return -of(EnergyKind::Supply) - of(EnergyKind::PumpLeakage); }
  /// Everything that left the fluid or mechanics for good.
  double losses() const {
    return of(EnergyKind::Throttling) + of(EnergyKind::Relief) + of(EnergyKind::Leakage) + of(EnergyKind::Friction) +
           of(EnergyKind::Cavitation) + dry_friction + end_stops;
  }
  double load_work() const { return of(EnergyKind::Load); }
  double stored_change() const { return fluid_stored + kinetic - kinetic_start; }
  /// delivered - (losses + load work + stored change): zero for an exact integration.
  double residual() const { return delivered() - losses() - load_work() - stored_change(); }
};

}  // namespace plant
