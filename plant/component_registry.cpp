// The list of component types, and the lookups on a type's tables.
#include <array>

#include "plant/axial_piston_pump.h"
#include "plant/component_type.h"
#include "plant/differential_cylinder.h"
#include "plant/flow_source.h"
#include "plant/fluid.h"
#include "plant/hydraulic_motor.h"
#include "plant/hydraulic_volume.h"
#include "plant/orifice.h"
#include "plant/pressure_sensor.h"
#include "plant/proportional_valve.h"
#include "plant/relief_valve.h"
#include "plant/rotary_shaft.h"
#include "plant/tank.h"

namespace plant {

int ComponentType::parameter_index(std::string_view parameter) const {
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].name == parameter) return static_cast<int>(i);
  return -1;
}

int ComponentType::connector_index(std::string_view connector) const {
  for (std::size_t i = 0; i < connectors.size(); ++i)
    if (connectors[i].name == connector) return static_cast<int>(i);
  return -1;
}

std::vector<double> ComponentType::default_values() const {
  std::vector<double> values;
  values.reserve(parameters.size());
  for (const auto& p : parameters) values.push_back(p.default_value);
  return values;
}

std::span<const ComponentType* const> component_types() {
  static const std::array<const ComponentType*, 12> kTypes{
      &Fluid::type_info(),          &Tank::type_info(),          &HydraulicVolume::type_info(),
      &AxialPistonPump::type_info(), &ReliefValve::type_info(),  &ProportionalValve::type_info(),
      &DifferentialCylinder::type_info(), &HydraulicMotor::type_info(), &RotaryShaft::type_info(),
      &PressureSensor::type_info(), &Orifice::type_info(),       &FlowSource::type_info(),
  };
  return kTypes;
}

const ComponentType* find_component_type(std::string_view name) {
  for (const ComponentType* t : component_types())
    if (t->name == name) return t;
  return nullptr;
}

}  // namespace plant
