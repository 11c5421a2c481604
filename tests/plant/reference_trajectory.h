// The 20 s reference-plant trajectory that guards the plant's numerics against speed work
// (issue 14): the reference plant at its default 1 ms step, driven the way the devices would drive
// it - the pump held at 60 % swivel, the cylinder following a sine by a position loop and then
// driven into both end stops twice, the motor swept, braked by closing its valve, and restarted.
// tests/data/plant/reference_trajectory.csv holds the trajectory the plant produced before the
// speed work (commit 7dfbef7); reference_trajectory_dump writes that file.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "plant/plant.h"
#include "plant/reference_plant.h"

namespace plant::testing {

inline constexpr std::array<const char*, 10> kTrajectorySignals = {
    "cyl.position",      "cyl.velocity",        "cyl.pressure_a",   "cyl.pressure_b",   "shaft.angle",
    "shaft.speed",       "motor.pressure_a",    "motor.pressure_b", "p_supply.pressure", "pump.swivel_angle"};
inline constexpr int kTrajectorySampleTicks = 20;  // one sample every 20 ms
inline constexpr long kTrajectoryTicks = 20000;    // 20 s of 1 ms ticks

struct RecordedTrajectory {
  std::vector<std::array<double, kTrajectorySignals.size()>> samples;
  /// Ticks (1 ms, counted from 0) after which the cylinder rests on a stop it was not on before;
  /// positive: the upper stop, negative: the lower one (tick + 1, so tick 0 keeps its sign).
  std::vector<long> stop_arrivals;
};

inline RecordedTrajectory record_reference_trajectory() {
  Plant p(reference_plant_description());
  (void)p.set_parameter("cyl.load_force", 3000.0);
  (void)p.set_parameter("shaft.load_torque", 5.0);
  double* pilot = p.port("pump.pilot_command");
  const double* alpha = p.port("pump.swivel_angle");
  double* cyl_a = p.port("valve_cyl.solenoid_a_current");
  double* cyl_b = p.port("valve_cyl.solenoid_b_current");
  double* motor_a = p.port("valve_motor.solenoid_a_current");
  const double* position = p.port("cyl.position");
  std::array<const double*, kTrajectorySignals.size()> signals{};
  for (std::size_t i = 0; i < signals.size(); ++i) signals[i] = p.port(kTrajectorySignals[i]);

  RecordedTrajectory out;
  const double stroke = *p.parameter("cyl.stroke");
  auto stop_of = [&](double x) { return x >= stroke - 1e-9 ? 1 : x <= 1e-9 ? -1 : 0; };
  int on_stop = stop_of(*position);  // -1 lower, +1 upper (it starts on the lower one)
  sim::Time now{};
  const sim::Duration tick = sim::milliseconds(1);
  for (long k = 0; k < kTrajectoryTicks; ++k) {
    const double t = static_cast<double>(k) * 1e-3;
    *pilot = 4.0 * (0.6 - *alpha);
    double u = 0.0;  // cylinder valve command, -1..1
    const double cycle = std::fmod(t, 10.0);
    if (cycle < 6.0) {
      const double target = 0.25 + 0.15 * std::sin(2 * std::numbers::pi * 0.2 * cycle);
      u = std::clamp(40.0 * (target - *position), -1.0, 1.0);
    } else {
      u = cycle < 8.0 ? 0.8 : -0.8;
    }
    *cyl_a = u > 0 ? 0.128 + 0.64 * u : 0.0;  // the DSV's Imin/Imax mapping
    *cyl_b = u < 0 ? 0.128 - 0.64 * u : 0.0;
    *motor_a = (t < 7.0 || t >= 12.0) ? 0.6 + 0.3 * std::sin(2 * std::numbers::pi * 0.2 * t) : 0.0;
    p.step(now, tick);
    now += tick;
    const int stop = stop_of(*position);
    if (stop != 0 && stop != on_stop) out.stop_arrivals.push_back(stop * (k + 1));
    on_stop = stop;
    if ((k + 1) % kTrajectorySampleTicks == 0) {
      auto& row = out.samples.emplace_back();
      for (std::size_t i = 0; i < signals.size(); ++i) row[i] = *signals[i];
    }
  }
  return out;
}

}  // namespace plant::testing
