// The 116 objects of chapter 4: the table's totals as the digest's audit counted them, and every
// object on the bus (read command byte by size, access, sub-index, PDO-mappability).
#include "devices/vtvpcd/manufacturer_objects.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "tests/devices/vtvpcd/vtvpcd_fixture.h"

using namespace vtvpcd;
using vtest::Frame;

TEST(ManufacturerObjects, TableTotalsMatchTheManual) {
  const auto objects = manufacturer_objects();
  ASSERT_EQ(objects.size(), 116u);
  int rw4 = 0, rw2 = 0, ro4 = 0, ro2 = 0;
  std::map<double, int> scales;
  std::set<std::uint16_t> indices;
  for (const auto& o : objects) {
    (o.read_only ? (o.bytes() == 4 ? ro4 : ro2) : (o.bytes() == 4 ? rw4 : rw2))++;
    scales[o.scale.value()]++;
    indices.insert(o.index);
  }
  EXPECT_EQ(rw4, 54);
  EXPECT_EQ(rw2, 42);
  EXPECT_EQ(ro4, 17);
  EXPECT_EQ(ro2, 3);
  EXPECT_EQ(indices.size(), 116u);
  EXPECT_EQ(scales[327.7], 37);
  EXPECT_EQ(scales[327.67], 32);
  EXPECT_EQ(scales[125.0], 32);
  EXPECT_EQ(scales[1.0], 8);
  EXPECT_EQ(scales[128.0], 4);
  EXPECT_EQ(scales[12.6], 1);
  EXPECT_EQ(scales[324.7], 1);
  EXPECT_EQ(scales[150.0], 1);
}

TEST(ManufacturerObjects, CompactIndexMap) {
  for (int k = 0; k < 16; ++k) {
    const auto kk = static_cast<std::uint16_t>(k);
    EXPECT_NE(find_object_spec(0x2001 + kk), nullptr);
    EXPECT_NE(find_object_spec(0x2023 + kk), nullptr);
    EXPECT_NE(find_object_spec(0x2045 + kk), nullptr);
    EXPECT_NE(find_object_spec(0x2101 + kk), nullptr);
    EXPECT_NE(find_object_spec(0x2123 + kk), nullptr);
  }
  for (int g = 0; g < 4; ++g) {
    EXPECT_NE(find_object_spec(static_cast<std::uint16_t>(0x2323 + 4 * g)), nullptr);
    EXPECT_NE(find_object_spec(static_cast<std::uint16_t>(0x2423 + 4 * g)), nullptr);
  }
  EXPECT_EQ(find_object_spec(0x2011), nullptr);
  EXPECT_EQ(find_object_spec(0x2324), nullptr);
  EXPECT_STREQ(find_object_spec(0x2C76)->name, "Power CMD (BUS)");
  EXPECT_STREQ(find_object_spec(0x2F2A)->section, "4.116");
  EXPECT_EQ(find_object_spec(0x2F2A)->type, canopen::DataType::Integer16);
  EXPECT_EQ(find_object_spec(0x2C67)->type, canopen::DataType::Unsigned32);
  EXPECT_EQ(find_object_spec(0x2101)->type, canopen::DataType::Unsigned16);  // raw reaches 37500
}

TEST(ManufacturerObjects, EveryObjectOnTheBus) {
  vtest::Vtvpcd n;
  for (const auto& o : manufacturer_objects()) {
    SCOPED_TRACE(o.name);
    const auto lo = static_cast<std::uint8_t>(o.index), hi = static_cast<std::uint8_t>(o.index >> 8);
    // Read: 0x43 for 4-byte objects, 0x4B for 2-byte ones, the start-up raw value little-endian.
    auto r = n.sdo({0x40, lo, hi, 0x00});
    ASSERT_EQ(r.size(), 8u);
    EXPECT_EQ(r[0], o.bytes() == 4 ? 0x43 : 0x4B);
    EXPECT_EQ(r[1], lo);
    EXPECT_EQ(r[2], hi);
    if (!o.read_only) {
      const auto v = static_cast<std::uint32_t>(o.start_raw);
      EXPECT_EQ(r[4], static_cast<std::uint8_t>(v));
      EXPECT_EQ(r[5], static_cast<std::uint8_t>(v >> 8));
    }
    // Sub-index 1 does not exist.
    EXPECT_EQ(n.sdo({0x40, lo, hi, 0x01}), (std::vector<std::uint8_t>{0x80, lo, hi, 0x01, 0x11, 0x00, 0x09, 0x06}));
    // Read-only: "only reading or writing possible".
    if (o.read_only) {
      EXPECT_EQ(n.sdo({0x23, lo, hi, 0x00, 1, 0, 0, 0}),
                (std::vector<std::uint8_t>{0x80, lo, hi, 0x00, 0x00, 0x00, 0x01, 0x06}));
    }
    const auto* e = n.od().entry(o.index, 0);
    ASSERT_NE(e, nullptr);
    EXPECT_TRUE(e->pdo_mappable);
    EXPECT_EQ(e->name, o.name);
  }
}

TEST(ManufacturerObjects, UndocumentedIndicesDoNotExist) {
  vtest::Vtvpcd n;
  int missing = 0;
  for (std::uint32_t index = 0x2000; index <= 0x5FFF; ++index) {
    if (find_object_spec(static_cast<std::uint16_t>(index))) continue;
    if (!n.od().object(static_cast<std::uint16_t>(index))) ++missing;
  }
  EXPECT_EQ(missing, 0x4000 - 116);
  EXPECT_EQ(n.sdo({0x40, 0x11, 0x20, 0x00}), (std::vector<std::uint8_t>{0x80, 0x11, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06}));
}
