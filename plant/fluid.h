// The hydraulic fluid: density and effective bulk modulus, optionally softened at low pressure by
// entrained (undissolved) air. One per plant; every pressure node uses it.
//
// With an air volume fraction a0 at atmospheric pressure pa and polytropic index k, the air at
// absolute pressure P occupies x = a0 (pa/P)^(1/k) per unit of liquid-plus-air volume at pa, its
// fraction of the mixture is r = x / (1 - a0 + x), and the mixture's bulk modulus is
//     1/beta(P) = (1 - r)/beta_liquid + r/(k P)
// (series compliance of liquid and gas; the common textbook model, e.g. Merritt, Hydraulic Control
// Systems, and the review by Gholizadeh et al. 2011). With a0 = 0 it is the constant beta_liquid.
#pragma once

#include "plant/component.h"

namespace plant {

class Fluid final : public Component {
 public:
  enum Param {
    kDensity,
    kBulkModulus,
    kAirFraction,
    kPolytropicIndex,
    kAtmosphericPressure,
    kVapourPressure,
    kParamCount
  };
  static const ComponentType& type_info();

  Fluid(std::string name, std::vector<double> values);

  double density() const { return parameter(kDensity); }
  /// Effective bulk modulus (Pa) at gauge pressure p (Pa); with `slope`, also d(beta)/dp.
  double bulk_modulus(double p, double* slope = nullptr) const;
  /// Lowest gauge pressure the liquid sustains (Pa): below it, it cavitates (vapour fills the
  /// space), so node pressures are held at or above it.
  double cavitation_pressure() const { return parameter(kVapourPressure) - parameter(kAtmosphericPressure); }
};

}  // namespace plant
