// Speed of the reference plant alone: simulated seconds per wall second, and the cost of one
// physics step, for the default step size and two finer ones. The plant is driven the way the
// devices would drive it (pump held at a swivel angle by a position loop, the cylinder valve
// stroking the cylinder back and forth, the motor valve running the motor up and down), so the
// bodies move and the valves meter throughout.
//
// Figures are per CPU second of this process (CLOCK_PROCESS_CPUTIME_ID), so a loaded machine
// changes them less than wall time. The split between the hydraulics and ODE comes from a second
// run with the tick profile on (sim/tick_profile.h), scaled to the first run's CPU time.
//
// Usage: plant_bench [simulated_seconds]   (default 20)
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "plant/plant.h"
#include "plant/reference_plant.h"
#include "plant/rigid_body_world.h"
#include "sim/tick_profile.h"

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
  std::uint64_t ode_steps;
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
  // The valve currents, computed before the clock starts (two sin() per tick would be a tenth of
  // the plant's own time); the pump's loop closes on the plant's output, so it stays in the loop.
  struct Currents {
    double cyl_a, cyl_b, mot_a;
  };
  std::vector<Currents> currents(static_cast<std::size_t>(ticks));
  for (long k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) * 1e-3;
    const double s = std::sin(2.0 * M_PI * 0.25 * t);  // cylinder: 4 s period, full strokes
    currents[static_cast<std::size_t>(k)] = {s > 0 ? 0.128 + 0.5 * s : 0.0, s < 0 ? 0.128 - 0.5 * s : 0.0,
                                             0.6 + 0.3 * std::sin(2.0 * M_PI * 0.2 * t)};
  }
  sim::Time now{};
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = cpu_seconds();
  for (const Currents& c : currents) {
    *pilot = 4.0 * (0.6 - *alpha);  // the pump controller's swivel-angle loop, at 60 %
    *cyl_a = c.cyl_a;
    *cyl_b = c.cyl_b;
    *mot_a = c.mot_a;
    p.step(now, tick);
    now += tick;
  }
  const double cpu = cpu_seconds() - cpu0;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return {wall, cpu, p.physics_steps(), p.ode_steps()};
}

// The rigid bodies alone: the reference plant's two bodies (slider with stops and friction motor,
// hinge with friction motor) under a changing force, one RigidBodyWorld::step per step (ODE steps
// a body only when its constraints have no closed form: here when the slider leaves a stop).
struct BodyFigures {
  double ns_per_step;
  double ode_share;
};

BodyFigures rigid_body_step(long steps) {
  plant::RigidBodyWorld world;
  const plant::DofId rod = world.add_slider(0.0, 0.5, 0.25);
  const plant::DofId shaft = world.add_hinge(0.0);
  world.set_mass(rod, 200.0);
  world.set_mass(shaft, 0.25);
  std::vector<double> force(2), limit{250.0, 0.5};
  const double cpu0 = cpu_seconds();
  for (long k = 0; k < steps; ++k) {
    force[0] = (k / 500) % 2 == 0 ? 2000.0 : -2000.0;
    force[1] = 20.0;
    world.step(1e-3, force, limit);
  }
  return {(cpu_seconds() - cpu0) / static_cast<double>(steps) * 1e9,
          static_cast<double>(world.ode_steps()) / static_cast<double>(steps)};
}

}  // namespace

int main(int argc, char** argv) {
  const double seconds = argc > 1 ? std::atof(argv[1]) : 20.0;
  fmt::print("reference plant alone, 1 ms ticks, {} s simulated per run\n", seconds);
  fmt::print("{:>10} {:>14} {:>14} {:>14} {:>16} {:>11}\n", "max_step", "sim s/wall s", "sim s/CPU s", "ns/tick (CPU)",
             "ns/physics step", "ODE steps");
  for (double max_step : {1e-3, 5e-4, 2.5e-4}) {
    const Figures f = run(max_step, seconds);
    fmt::print("{:>8.2f}ms {:>14.0f} {:>14.0f} {:>14.0f} {:>16.0f} {:>10.1f}%\n", max_step * 1e3, seconds / f.wall,
               seconds / f.cpu, f.cpu / (seconds * 1000.0) * 1e9, f.cpu / static_cast<double>(f.steps) * 1e9,
               100.0 * static_cast<double>(f.ode_steps) / static_cast<double>(f.steps));
  }
  // The split at the default step: a second run with the probes on.
  const Figures plain = run(1e-3, seconds);
  const double overhead = sim::TickProfile::probe_overhead_ns();
  sim::TickProfile profile;
  sim::TickProfile::active = &profile;
  const std::int64_t t0 = sim::TickProfile::now_ns();
  run(1e-3, seconds);
  const double total = profile.run_ns_without_probes(sim::TickProfile::now_ns() - t0, overhead);
  sim::TickProfile::active = nullptr;
  const double tick_ns = plain.cpu / (seconds * 1000.0) * 1e9;
  auto share = [&](sim::TickPart part) { return profile.part_ns(part, overhead) / total; };
  const double ode = share(sim::TickPart::Ode), plant = share(sim::TickPart::Plant) - ode;
  fmt::print("split at 1 ms ({:.0f} ns/tick CPU): hydraulics and plant {:.0f} ns ({:.0f} %), ODE {:.0f} ns ({:.0f} %), "
             "bench loop {:.0f} ns\n",
             tick_ns, plant * tick_ns, 100 * plant, ode * tick_ns, 100 * ode, (1 - plant - ode) * tick_ns);
  const BodyFigures bodies = rigid_body_step(static_cast<long>(seconds * 1000.0));
  fmt::print("rigid bodies alone (the two bodies, one RigidBodyWorld::step per physics step): {:.0f} ns per step, "
             "ODE stepped in {:.0f} % of them\n",
             bodies.ns_per_step, 100 * bodies.ode_share);
  return 0;
}
