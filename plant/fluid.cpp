#include "plant/fluid.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace plant {
namespace {

const std::array<ParameterSpec, Fluid::kParamCount> kParams{{
    {"density", "kg/m^3", 870.0, 0.0, 2000.0, true, "mass density (HLP 46 mineral oil at 15 C: 870-880)"},
    {"bulk_modulus", "Pa", 1.4e9, 0.0, 1e11, true,
     "effective bulk modulus of the air-free liquid including hose compliance"},
    {"air_fraction", "1", 0.0, 0.0, 0.5, false, "entrained air volume fraction at atmospheric pressure (0 = none)"},
    {"polytropic_index", "1", 1.4, 1.0, 1.4, false, "polytropic exponent of the air (1 isothermal, 1.4 adiabatic)"},
    {"atmospheric_pressure", "Pa", 101325.0, 0.0, 2e5, true, "absolute pressure that gauge 0 Pa corresponds to"},
    {"vapour_pressure", "Pa", 1000.0, 0.0, 1e5, true,
     "absolute pressure at which the liquid cavitates; node pressures never fall below it"},
}};

const ComponentType kType{
    "fluid",
    "hydraulic fluid: density, effective bulk modulus, entrained air",
    kParams,
    {},
    {},
    nullptr,
    make_component<Fluid>,
};

}  // namespace

const ComponentType& Fluid::type_info() { return kType; }

Fluid::Fluid(std::string name, std::vector<double> values)
    : Component(kType, std::move(name), std::move(values)) {
  declare_hooks(0u);
}

double Fluid::bulk_modulus(double p, double* slope) const {
  const double a0 = parameter(kAirFraction);
  const double beta_l = parameter(kBulkModulus);
  const double pa = parameter(kAtmosphericPressure);
  if (a0 <= 0.0) {
    if (slope != nullptr) *slope = 0.0;
    return beta_l;
  }
  const double k = parameter(kPolytropicIndex);
  const double p_min = parameter(kVapourPressure);
  const bool floored = p + pa < p_min;
  const double P = floored ? p_min : p + pa;
  const double c = 1.0 - a0;
  const double x = a0 * std::pow(pa / P, 1.0 / k);
  const double r = x / (c + x);
  const double compliance = (1.0 - r) / beta_l + r / (k * P);
  const double beta = 1.0 / compliance;
  if (slope != nullptr) {
    if (floored) {
      *slope = 0.0;
    } else {
      const double dr_dP = -(x / (k * P)) * c / ((c + x) * (c + x));
      const double dC_dP = dr_dP * (1.0 / (k * P) - 1.0 / beta_l) - r / (k * P * P);
      *slope = -beta * beta * dC_dP;
    }
  }
  return beta;
}

}  // namespace plant
