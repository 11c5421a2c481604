// A 4/3 proportional directional valve (NG6 class, two solenoids, spring-centred spool).
//
// Spool: each solenoid's force is taken linear in its current above a preload current and
// saturates at full stroke, so the spool's commanded position is
//     u = f(I_A) - f(I_B),  f(I) = clamp((|I| - I_preload) / (I_full - I_preload), 0, 1),
// and the spool follows u as a second-order system (natural frequency, damping), |x| <= 1.
// A stuck spool (fault) stays where it is whatever the currents.
//
// Flow: the metering edges open past the overlap, a(x) = clamp((x - overlap)/(1 - overlap), 0, 1):
//     x > 0: P->A and B->T open by a(x);   x < 0: P->B and A->T open by a(-x);
// each edge passes Q = Kv * a * regroot(dp) (orifice_law.h) with Kv = Q_rated / sqrt(dp_rated)
// per edge, so the rated flow passes at the rated drop per edge; every edge also leaks
// Q = C_leak * dp (clearance leakage, which makes a centred valve drift a loaded actuator).
#pragma once

#include "plant/component.h"
#include "plant/second_order_lag.h"

namespace plant {

class ProportionalValve final : public Component {
 public:
  enum Param {
    kRatedFlow,
    kRatedPressureDrop,
    kOverlap,
    kCurrentPreload,
    kCurrentFull,
    kSpoolNaturalFrequency,
    kSpoolDamping,
    kLeakageCoefficient,
    kTransitionPressure,
    kStuck,
    kParamCount
  };
  enum Connector { kP, kT, kA, kB };
  enum Signal { kSolenoidACurrent, kSolenoidBCurrent, kSpoolPosition, kFlowA, kFlowB, kSignalCount };
  static const ComponentType& type_info();

  ProportionalValve(std::string name, std::vector<double> values);

  void read_inputs() override;
  void configure_step(double h) override;
  void advance(double h) override;
  void stamp(Equations& eq) const override;
  void publish(const CircuitState& state, double dt) override;

 private:
  void parameters_changed() override;
  /// Spool position commanded by the currents (normalised, -1..1).
  double commanded_position(double current_a, double current_b) const;
  /// Metering opening (0..1) of an edge for spool position s (s = x for P->A/B->T, -x otherwise).
  double opening(double s) const;
  /// The values an edge's stamp needs, read once per stamp() before anything is stamped (the
  /// stamps store doubles, so the compiler would otherwise reload every one of them per edge).
  struct EdgeLaw {
    double kv, leakage, transition;
  };
  static void stamp_edge(Equations& eq, NodeId from, NodeId to, double dp, double open, const EdgeLaw& law);
  double edge_flow(const CircuitState& state, int from, int to, double open) const;

  SecondOrderLag spool_;
  double command_ = 0.0;
  double kv_ = 0.0;
  double h_ = 0.0;
  // Edge openings averaged over the current step (P->A = B->T, and P->B = A->T).
  double open_forward_ = 0.0;
  double open_reverse_ = 0.0;
};

}  // namespace plant
