// A variable-displacement axial-piston pump (A4VS class) driven at constant speed by an electric
// motor, its swash plate positioned by a hydraulic stroking piston under a proportional pilot valve
// (HS4-type control), as the VT-VPCD pump controller expects.
//
// Pilot valve: command u in [-1, 1] (the controller's valve command +-100 %) -> pilot spool x
// through second-order dynamics (natural frequency, damping), |x| <= 1.
// Swash plate: the pilot spool meters oil into the stroking piston, so the normalised swivel angle
// integrates the spool opening: d(alpha)/dt = (x + zero_offset) / stroke_time, alpha clamped to
// [alpha_min, alpha_max]. Its rate is thereby limited to 1/stroke_time (full pilot opening); at
// steady state the spool is centred, as in the real pump.
// Flow from A to B: Q = Vg/(2 pi) * alpha * n - C_leak * (p_B - p_A), with C_leak from the
// volumetric efficiency at rated pressure and full displacement: C_leak = (1 - eta_v) Vg n/(2 pi p_rated),
// so Q = Vg * n * eta_v at alpha = 1 and rated pressure.
// LVDT: the swivel-angle sensor reads gain * alpha + offset.
#pragma once

#include "plant/component.h"
#include "plant/second_order_lag.h"

namespace plant {

class AxialPistonPump final : public Component {
 public:
  enum Param {
    kDisplacement,
    kDriveSpeed,
    kVolumetricEfficiency,
    kHydromechanicalEfficiency,
    kRatedPressure,
    kAlphaMin,
    kAlphaMax,
    kStrokeTime,
    kPilotNaturalFrequency,
    kPilotDamping,
    kPilotZeroOffset,
    kLvdtGain,
    kLvdtOffset,
    kInitialSwivelAngle,
    kParamCount
  };
  enum Connector { kA, kB };
  enum Signal {
    kPilotCommand,
    kSwivelAngle,
    kLvdt,
    kPilotSpoolPosition,
    kPressureA,
    kPressureB,
    kDriveSpeedOut,
    kFlow,
    kDriveTorque,
    kSignalCount
  };
  static const ComponentType& type_info();

  AxialPistonPump(std::string name, std::vector<double> values);

  double swivel_angle() const { return alpha_; }
  double geometric_flow(double alpha) const;  ///< Vg/(2 pi) alpha n, m^3/s
  double leakage_coefficient() const { return leak_; }

  void read_inputs() override;
  void configure_step(double h) override;
  void advance(double h) override;
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;

 private:
  void parameters_changed() override;

  SecondOrderLag pilot_;
  double command_ = 0.0;
  double alpha_ = 0.0;
  double alpha_mid_ = 0.0;  ///< swivel angle averaged over the current step
  double leak_ = 0.0;
  double h_ = 0.0;
};

}  // namespace plant
