// Nothing allocates per step: after the first tick, stepping the reference plant makes no heap
// allocation at all - not in the plant's code, not in Eigen, not in ODE.
//
// Normal builds count every malloc/calloc/realloc of the process (the test binary interposes
// them over glibc's). Under AddressSanitizer, which owns malloc, only operator new is counted.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "plant/plant.h"
#include "plant/reference_plant.h"

namespace {
std::atomic<long> g_allocations{0};
}

#if defined(__SANITIZE_ADDRESS__)
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// GCC cannot see that these pair with the operator new above.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop
#else
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
}
#endif

namespace plant {
namespace {

TEST(Allocation, SteppingTheReferencePlantDoesNotAllocate) {
  const long at_start = g_allocations.load();
  Plant p(reference_plant_description());
  ASSERT_GT(g_allocations.load() - at_start, 100) << "the counting hook must see the plant being built";
  p.set_energy_accounting(true);
  double* current = p.port("valve_cyl.solenoid_a_current");
  double* motor = p.port("valve_motor.solenoid_b_current");
  double* pilot = p.port("pump.pilot_command");
  sim::Time now{};
  p.step(now, sim::milliseconds(1));  // the first tick sizes the step discretisations
  const long before = g_allocations.load();
  for (int k = 0; k < 3000; ++k) {
    *current = k > 500 && k < 2000 ? 0.6 : 0.0;  // cylinder runs into its end stop
    *motor = k > 200 ? 0.8 : 0.0;
    *pilot = k > 100 ? 0.5 : 0.0;
    p.step(now, sim::milliseconds(1));
    now += sim::milliseconds(1);
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace plant
