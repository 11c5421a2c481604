// A fixed-displacement hydraulic motor (bent-axis or axial piston, A2FM class) on a shaft.
//
// Flow A->B turns the shaft positively: Q_A = D/(2 pi) w + C_leak (p_A - p_B) leaves node A and
// enters node B; torque on the shaft D/(2 pi) (p_A - p_B), less the mechanical loss
// (1 - eta_hm) |D/(2 pi) (p_A - p_B)|, which acts as dry friction (it opposes motion and holds the
// shaft at rest like a breakaway torque) so the motor delivers eta_hm D dp/(2 pi) while turning.
// C_leak follows from the volumetric efficiency at rated pressure and speed:
// eta_v = D w/(2 pi) / (D w/(2 pi) + C_leak p)  =>  C_leak = (1/eta_v - 1) D w_rated / (2 pi p_rated).
#pragma once

#include "plant/component.h"

namespace plant {

class HydraulicMotor final : public Component {
 public:
  enum Param {
    kDisplacement,
    kVolumetricEfficiency,
    kMechanicalEfficiency,
    kRatedPressure,
    kRatedSpeed,
    kRotorInertia,
    kPortVolume,
    kParamCount
  };
  enum Connector { kA, kB, kShaft };
  enum Signal { kPressureA, kPressureB, kFlow, kTorque, kSignalCount };
  static const ComponentType& type_info();

  HydraulicMotor(std::string name, std::vector<double> values);

  double displacement_per_radian() const { return d_rad_; }
  double leakage_coefficient() const { return leak_; }

  void add_volumes(const CircuitState& state, std::vector<double>& node_volume) const override;
  void add_inertia(std::vector<double>& dof_mass) const override;
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;

 private:
  void parameters_changed() override;

  double d_rad_ = 0.0;  // D / (2 pi), m^3/rad
  double leak_ = 0.0;
};

}  // namespace plant
