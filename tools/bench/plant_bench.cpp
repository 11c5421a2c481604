// Speed of the reference plant alone: simulated seconds per wall second, and the cost of one
// physics step, for the default step size and two finer ones. The plant is driven the way the
// devices would drive it (pump held at a swivel angle by a position loop, the cylinder valve
// stroking the cylinder back and forth, the motor valve running the motor up and down), so the
// bodies move and the valves meter throughout.
//
// Usage: plant_bench [simulated_seconds]   (default 20)
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>

#include "plant/plant.h"
#include "plant/reference_plant.h"

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Figures {
  double wall;
  double cpu;
  std::uint64_t steps;
};

Figures run(double max_step, double seconds) {
  auto description = plant::reference_plant_description();
  description.solver.max_step = max_step;
  plant::Plant p(description);
  double* pilot = p.port("pump.pilot_command");
  const double* alpha = p.port("pump.swivel_angle");
  double* cyl_a = p.port("valve_cyl.solenoid_a_current");
  double* cyl_b = p.port("valve_cyl.solenoid_b_current");
  double* mot_a = p.port("valve_motor.solenoid_a_current");
  const sim::Duration tick = sim::milliseconds(1);
  const auto ticks = static_cast<long>(seconds * 1000.0);
  sim::Time now{};
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = cpu_seconds();
  for (long k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) * 1e-3;
    *pilot = 4.0 * (0.6 - *alpha);  // the pump controller's swivel-angle loop, at 60 %
    const double s = std::sin(2.0 * M_PI * 0.25 * t);  // cylinder: 4 s period, full strokes
    *cyl_a = s > 0 ? 0.128 + 0.5 * s : 0.0;
    *cyl_b = s < 0 ? 0.128 - 0.5 * s : 0.0;
    *mot_a = 0.6 + 0.3 * std::sin(2.0 * M_PI * 0.2 * t);
    p.step(now, tick);
    now += tick;
  }
  const double cpu = cpu_seconds() - cpu0;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return {wall, cpu, p.physics_steps()};
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 20.0;
  fmt::print("reference plant alone, 1 ms ticks, {} s simulated per run\n", seconds);
  fmt::print("{:>10} {:>14} {:>14} {:>14} {:>16}\n", "max_step", "sim s/wall s", "sim s/CPU s", "ns/tick (CPU)",
             "ns/physics step");
  for (double max_step : {1e-3, 5e-4, 2.5e-4}) {
    const Figures f = run(max_step, seconds);
    fmt::print("{:>8.2f}ms {:>14.0f} {:>14.0f} {:>14.0f} {:>16.0f}\n", max_step * 1e3, seconds / f.wall, seconds / f.cpu,
               f.cpu / (seconds * 1000.0) * 1e9, f.cpu / static_cast<double>(f.steps) * 1e9);
  }
  return 0;
}
