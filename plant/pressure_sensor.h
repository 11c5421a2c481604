// A pressure transducer on a node: the node pressure through an optional first-order lag (its
// response time), published once per tick for a device to read.
#pragma once

#include "plant/component.h"

namespace plant {

class PressureSensor final : public Component {
 public:
  enum Param { kTimeConstant, kParamCount };
  enum Connector { kPort };
  enum Signal { kPressure, kSignalCount };
  static const ComponentType& type_info();

  PressureSensor(std::string name, std::vector<double> values);
  void publish(const CircuitState& state, double dt) override;

 private:
  bool started_ = false;
  // The lag's gain 1 - exp(-dt/tau) per tick, for the tick length and time constant it was
  // computed for (both rarely change).
  double gain_dt_ = -1.0, gain_tau_ = -1.0, gain_ = 0.0;
};

}  // namespace plant
