// What 1010h/1011h do to the DSV's own objects (devices/dsv/dsv_stored_objects.h), through SDO.
#include <gtest/gtest.h>

#include "tests/devices/dsv/dsv_fixture.h"

using namespace dsvtest;

namespace {
constexpr std::uint32_t kSave = 0x65766173, kLoad = 0x64616F6C;
}  // namespace

// The characteristic points are no dictionary entries: a save of all parameters (sub 1) stores
// them too, and a restore waiting for the next reset is forgotten by a power cycle.
TEST_F(DsvTest, APowerCycleForgetsAPendingRestoreOfTheCharacteristicPoints) {
  make(bus_mode({{"dither_amplitude", "0"}}), "", 0, temp_store("stored_points"));
  ASSERT_EQ(write(0x2344, 3, 6, 2), 0u);
  ASSERT_EQ(write(0x2344, 5, 200, 2), 0u);
  ASSERT_EQ(write(0x1010, 1, kSave, 4), 0u);
  ASSERT_EQ(write(0x1011, 1, kLoad, 4), 0u);
  power_cycle();
  h->take();
  ASSERT_EQ(write(0x2344, 3, 6, 2), 0u);
  EXPECT_EQ(read(0x2344, 5), 200);  // loaded from the memory, not reset
}

// in mode 7, 230Eh:01 shows 250Eh:01; a save puts its own value back first, so the
// memory holds 230Eh's own value.
TEST_F(DsvTest, ASaveInMode7StoresTheAliasedObjectsOwnValue) {
  make(bus_mode({{"control_mode", "4"}, {"alias_230e_mode7", "true"}}), "controller", 0, temp_store("stored_alias"));
  const std::int64_t own = read(0x230E, 1);
  ASSERT_EQ(write(0x6043, 0, 7, 1), 0u);
  ASSERT_EQ(write(0x250E, 1, static_cast<std::uint32_t>(own + 1), 4), 0u);
  ASSERT_EQ(read(0x230E, 1), own + 1);  // the alias shows 250Eh:01
  ASSERT_EQ(write(0x1010, 1, kSave, 4), 0u);
  const auto* stored = dev->node().store().memory().find(0x230E, 1);
  ASSERT_NE(stored, nullptr);
  ASSERT_EQ(stored->bytes.size(), 4u);
  EXPECT_EQ(canopen::decode_unsigned(stored->bytes), static_cast<std::uint64_t>(own));
}
