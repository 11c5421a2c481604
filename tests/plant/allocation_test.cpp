// Nothing allocates per step: after the first tick, stepping the reference plant makes no heap
// allocation through operator new (Eigen, the standard library, the plant's own code). ODE's
// C allocations are not counted here; ODE reuses its step arena once it has grown.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "plant/plant.h"
#include "plant/reference_plant.h"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace plant {
namespace {

TEST(Allocation, SteppingTheReferencePlantDoesNotAllocate) {
  Plant p(reference_plant_description());
  p.set_energy_accounting(true);
  double* current = p.port("valve_cyl.solenoid_a_current");
  double* pilot = p.port("pump.pilot_command");
  sim::Time now{};
  p.step(now, sim::milliseconds(1));  // first tick sizes the step discretisations
  const long before = g_allocations.load();
  for (int k = 0; k < 2000; ++k) {
    *current = k > 500 ? 0.6 : 0.0;
    *pilot = k > 100 ? 0.5 : 0.0;
    p.step(now, sim::milliseconds(1));
    now += sim::milliseconds(1);
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace plant
