#include "devices/vtvpcd/builtin_pump_model.h"

#include <algorithm>
#include <cmath>

namespace vtvpcd {

namespace {
constexpr double kMaxSubstepS = 0.25e-3;
constexpr double kSpringCentringS = 0.2;
constexpr double kMinPilotPressureBar = 10.0;
}  // namespace

BuiltinPumpModel::BuiltinPumpModel(const BuiltinPlantSettings& settings, PumpType type)
    : s_(settings),
      type_(type),
      alpha_lo_(type == PumpType::A4VSG ? -100.0 : 0.0),
      alpha_hi_(100.0),
      k_load_(settings.k_load),
      speed_rpm_(settings.speed_rpm) {
  p_a_ = type == PumpType::A4VSG ? s_.p_boost_bar : s_.pA_const_bar;
  p_b_ = type == PumpType::A4VSG ? s_.p_boost_bar : 0.0;
}

double BuiltinPumpModel::flow_l_min() const {
  return s_.vg_max_cm3 * std::max(speed_rpm_, 0.0) * std::abs(alpha_) / 100.0 / 1000.0;
}

void BuiltinPumpModel::step(double spool_command_pct, double dt_s) {
  const int n = std::max(1, static_cast<int>(std::ceil(dt_s / kMaxSubstepS - 1e-9)));
  const double h = dt_s / n;
  for (int i = 0; i < n; ++i) substep(spool_command_pct, h);
}

void BuiltinPumpModel::substep(double u, double h) {
  // Pilot spool: first-order lag (exact discretisation, stable for any h).
  spool_ += (std::clamp(u, -100.0, 100.0) - spool_) * (1.0 - std::exp(-h / s_.tau_valve_s));

  // Swash plate: integrates the spool opening; spring centring without actuating pressure.
  const bool no_actuation = speed_rpm_ <= 0.0 ||
                            (s_.pilot_supply == PilotSupply::Internal && p_ < kMinPilotPressureBar);
  const double dalpha = no_actuation ? -alpha_ / kSpringCentringS : spool_ / s_.t_stroke_s;
  alpha_ = std::clamp(alpha_ + dalpha * h, alpha_lo_, alpha_hi_);

  // Pressure volume on the delivery port: dp/dt = beta/V * (Q_p - Q_L - Q_leak - Q_RV) / 60.
  const double q_pump = flow_l_min();
  const double q_load = k_load_ * std::sqrt(std::max(p_, 0.0));
  const double q_leak = s_.c_leak * p_;
  const double q_relief = s_.k_relief * std::max(p_ - s_.p_relief_bar, 0.0);
  p_ = std::max(0.0, p_ + s_.beta_bar / s_.oil_volume_l * (q_pump - q_load - q_leak - q_relief) / 60.0 * h);

  // Ports: A4VSO/A2V deliver at B; an A4VSG delivers at B or A by the swivel direction.
  if (type_ == PumpType::A4VSG) {
    p_b_ = alpha_ >= 0.0 ? p_ : s_.p_boost_bar;
    p_a_ = alpha_ >= 0.0 ? s_.p_boost_bar : p_;
  } else {
    p_b_ = p_;
    p_a_ = s_.pA_const_bar;
  }
}

}  // namespace vtvpcd
