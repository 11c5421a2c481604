#include "plant/pressure_sensor.h"

#include <array>
#include <cmath>

namespace plant {
namespace {

const std::array<ParameterSpec, PressureSensor::kParamCount> kParams{{
    {"time_constant", "s", 0.0, 0.0, 10.0, false, "first-order response time (0 = ideal)"},
}};
const std::array<ConnectorSpec, 1> kConnectors{{
    {"port", Domain::Fluid, false, "the node measured"},
}};
const std::array<SignalSpec, PressureSensor::kSignalCount> kSignals{{
    {"pressure", sim::PortDirection::Output, "Pa", "measured gauge pressure", sim::display::bar},
}};

const ComponentType kType{
    "pressure_sensor",
    "pressure transducer",
    kParams,
    kConnectors,
    kSignals,
    nullptr,
    make_component<PressureSensor>,
};

}  // namespace

const ComponentType& PressureSensor::type_info() { return kType; }

PressureSensor::PressureSensor(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(kPublishes);
}

void PressureSensor::publish(const CircuitState& state, double dt) {
  const double p = state.p(node(kPort));
  const double tau = parameter(kTimeConstant);
  if (!started_ || tau <= 0.0) {
    out(kPressure) = p;
    started_ = true;
    return;
  }
  if (dt != gain_dt_ || tau != gain_tau_) {
    gain_ = 1.0 - std::exp(-dt / tau);
    gain_dt_ = dt;
    gain_tau_ = tau;
  }
  out(kPressure) += gain_ * (p - out(kPressure));
}

}  // namespace plant
