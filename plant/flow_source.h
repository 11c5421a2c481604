// An ideal flow source: a fixed volumetric flow from port A to port B whatever the pressures.
// For test circuits (a volume "fed by constant flow") and for idealised supplies.
#pragma once

#include "plant/component.h"

namespace plant {

class FlowSource final : public Component {
 public:
  enum Param { kFlow, kParamCount };
  enum Connector { kA, kB };
  static const ComponentType& type_info();

  FlowSource(std::string name, std::vector<double> values);
  void stamp(Equations& eq) const override;
};

}  // namespace plant
