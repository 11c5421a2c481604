// The continuous state the circuit solver integrates, and the handles components use to address
// it: pressure nodes (a shared pressure of connected fluid ports) and mechanical degrees of freedom
// (a cylinder rod on its slider, a shaft on its hinge).
#pragma once

#include <cstddef>
#include <vector>

namespace plant {

class Fluid;

struct NodeId {
  int index = -1;
};
struct DofId {
  int index = -1;
};

/// Where energy goes, for the energy balance. Components tag each flow and force with one.
enum class EnergyKind : int {
  Supply,       ///< ideal displacement of pumps and flow sources (power delivered, negative in the ledger)
  PumpLeakage,  ///< internal leakage of pumps (reduces what the pump delivers)
  Throttling,   ///< metering edges of valves, fixed orifices
  Relief,       ///< relief valves
  Leakage,      ///< valve, cylinder and motor leakage
  Friction,     ///< viscous friction stamped by components (dry friction is measured in ODE)
  Load,         ///< external load forces and torques
  Cavitation,   ///< vapour filling nodes held at the cavitation pressure (solver, not components)
  Internal,     ///< conversion between fluid and mechanics (piston areas, motor displacement): not a loss
};
inline constexpr int kEnergyKinds = static_cast<int>(EnergyKind::Internal);

/// Node pressures (states first, then fixed-pressure boundaries such as tanks), and per degree of
/// freedom its velocity and position (positions are advanced by ODE, not by the hydraulic solver).
struct CircuitState {
  std::vector<double> pressure;  ///< Pa (gauge)
  std::vector<double> velocity;  ///< m/s or rad/s
  std::vector<double> position;  ///< m (within the end stops) or rad (unbounded)
  int pressure_states = 0;       ///< nodes [0, pressure_states) are integrated; the rest are fixed
  const Fluid* fluid = nullptr;

  double p(NodeId n) const { return pressure[static_cast<std::size_t>(n.index)]; }
  double v(DofId d) const { return velocity[static_cast<std::size_t>(d.index)]; }
  double x(DofId d) const { return position[static_cast<std::size_t>(d.index)]; }
};

}  // namespace plant
