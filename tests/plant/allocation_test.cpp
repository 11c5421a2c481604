// Nothing allocates per step: after the first tick, stepping the reference plant makes no heap
// allocation at all - not in the plant's code, not in Eigen, not in ODE.
// (tests/support/counting_allocator.h says what is counted.)
#include <gtest/gtest.h>

#include "plant/plant.h"
#include "plant/reference_plant.h"
#include "tests/support/counting_allocator.h"

namespace plant {
namespace {

TEST(Allocation, SteppingTheReferencePlantDoesNotAllocate) {
  const long at_start = vtest::allocation_count();
  Plant p(reference_plant_description());
  ASSERT_GT(vtest::allocation_count() - at_start, 100) << "the counting hook must see the plant being built";
  p.set_energy_accounting(true);
  double* current = p.port("valve_cyl.solenoid_a_current");
  double* motor = p.port("valve_motor.solenoid_b_current");
  double* pilot = p.port("pump.pilot_command");
  sim::Time now{};
  p.step(now, sim::milliseconds(1));  // the first tick sizes the step discretisations
  const long before = vtest::allocation_count();
  for (int k = 0; k < 3000; ++k) {
    *current = k > 500 && k < 2000 ? 0.6 : 0.0;  // cylinder runs into its end stop
    *motor = k > 200 ? 0.8 : 0.0;
    *pilot = k > 100 ? 0.5 : 0.0;
    p.step(now, sim::milliseconds(1));
    now += sim::milliseconds(1);
  }
  EXPECT_EQ(vtest::allocation_count() - before, 0);
}

}  // namespace
}  // namespace plant
