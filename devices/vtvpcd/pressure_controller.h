// The pressure controller (digest §4.5): an ideal-form PI on the error in % of p_ref, with the
// gain Kp = Contr P / 128 and the integral time Ti = Contr I (ms) of the selected set's group.
// Its output is a swivel-angle demand ("pressure stroke", 0x2F32). Anti-windup by tracking:
// while another branch wins the minimum selection the integrator is pulled down to the resulting
// angle, so the pressure branch takes over without a jump when the pressure reaches its command.
#pragma once

#include <algorithm>

namespace vtvpcd {

class PressureController {
 public:
  struct Params {
    double kp = 1.0;
    double ti_ms = 100.0;
    double p_ref_bar = 350.0;
    double alpha_lo = 0.0;
    double alpha_hi = 100.0;
  };

  // Inline: once per control cycle.
  /// One control period: returns alpha_p (%).
  double update(double p_cmd_bar, double p_act_bar, const Params& p, double dt_s) {
    const double e = 100.0 * (p_cmd_bar - p_act_bar) / p.p_ref_bar;
    output_ = std::clamp(p.kp * e + integral_, p.alpha_lo, p.alpha_hi);
    // Kp = 0 freezes the controller: the output is the integrator, which no longer moves.
    integral_ = std::clamp(integral_ + p.kp * e * dt_s / (p.ti_ms / 1000.0), p.alpha_lo, p.alpha_hi);
    return output_;
  }
  /// The pressure branch lost the minimum selection to `alpha_res`: I <- min(I, alpha_res).
  void track(double alpha_res) { integral_ = std::min(integral_, alpha_res); }
  /// Controller off (not enabled or stopped): I := alpha_lo.
  void reset(double alpha_lo) {
    integral_ = alpha_lo;
    output_ = alpha_lo;
  }
  double output() const { return output_; }
  double integral() const { return integral_; }

 private:
  double integral_ = 0.0;
  double output_ = 0.0;
};

}  // namespace vtvpcd
