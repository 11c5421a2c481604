// A lumped volume of fluid: a hose, a pipe, a block's bores. It gives its node the capacitance
// V/beta in dp/dt = beta/V * (sum of inflows - dV/dt).
#pragma once

#include "plant/component.h"

namespace plant {

class HydraulicVolume final : public Component {
 public:
  enum Param { kVolume, kParamCount };
  enum Connector { kPort };
  static const ComponentType& type_info();

  HydraulicVolume(std::string name, std::vector<double> values);
  void add_volumes(const CircuitState& state, std::vector<double>& node_volume) const override;
};

}  // namespace plant
