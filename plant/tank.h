// A reservoir: a node at fixed pressure (0 Pa gauge for an open tank). Also usable as an ideal
// pressure source in test circuits.
#pragma once

#include "plant/component.h"

namespace plant {

class Tank final : public Component {
 public:
  enum Param { kPressure, kParamCount };
  enum Connector { kPort };
  static const ComponentType& type_info();

  Tank(std::string name, std::vector<double> values);
  void fix_pressures(CircuitState& state) const override;
};

}  // namespace plant
