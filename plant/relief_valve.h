// A pressure relief valve from P to T: closed below its cracking pressure, above it a flow that
// rises with the pressure-flow gradient of its characteristic (the catalogue's p-Q curve):
//     Q = (dp - p_crack) / gradient,   dp = p_P - p_T,
// with the corner smoothed over `transition_pressure` (Q = s(dp - p_crack)/gradient,
// s(u) = (u + sqrt(u^2 + d^2))/2), so the solver sees a continuous slope.
#pragma once

#include "plant/component.h"

namespace plant {

class ReliefValve final : public Component {
 public:
  enum Param { kCrackingPressure, kPressureGradient, kTransitionPressure, kParamCount };
  enum Connector { kP, kT };
  enum Signal { kFlow, kSignalCount };
  static const ComponentType& type_info();

  ReliefValve(std::string name, std::vector<double> values);
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;

 private:
  double flow(double dp, double* slope) const;
};

}  // namespace plant
