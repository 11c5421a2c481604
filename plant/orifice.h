// A fixed sharp-edged orifice (a throttle, a load restriction):
//     Q = Cd * A * sqrt(2 |dp| / rho) * sign(dp),  A = pi/4 d^2,
// with the regularised root of orifice_law.h.
#pragma once

#include "plant/component.h"

namespace plant {

class Orifice final : public Component {
 public:
  enum Param { kDiameter, kDischargeCoefficient, kTransitionPressure, kParamCount };
  enum Connector { kA, kB };
  enum Signal { kFlow, kSignalCount };
  static const ComponentType& type_info();

  Orifice(std::string name, std::vector<double> values);
  /// Flow coefficient K (m^3/s per sqrt(Pa)) for the given fluid density.
  double flow_coefficient(double density) const;
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;
};

}  // namespace plant
