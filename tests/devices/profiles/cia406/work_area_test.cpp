#include "devices/profiles/cia406/work_area.h"

#include <gtest/gtest.h>

namespace cia406 {
namespace {

TEST(WorkArea, InsideAboveBelowWithInclusiveLimitsAboveFirst) {
  EXPECT_EQ(work_area_state(0, 0, 16384), kWorkAreaInside);
  EXPECT_EQ(work_area_state(16384, 0, 16384), kWorkAreaInside);
  EXPECT_EQ(work_area_state(16385, 0, 16384), kWorkAreaAbove);
  EXPECT_EQ(work_area_state(-1, 0, 16384), kWorkAreaBelow);
  EXPECT_EQ(work_area_state(50, 100, 10), kWorkAreaAbove);  // low > high: "above" is tested first
}

}  // namespace
}  // namespace cia406
