#include "devices/canopen/object_dictionary.h"

#include <gtest/gtest.h>

#include "tests/devices/canopen/generic_node.h"

using namespace canopen;

TEST(ObjectDictionary, TypedAccessRoundTripsEveryWidth) {
  ObjectDictionary od;
  od.add_var(0x2000, "i8", DataType::Integer8, Access::ReadWrite, -3);
  od.add_var(0x2001, "u24", DataType::Unsigned24, Access::ReadWrite, 0xABCDEF);
  od.add_var(0x2002, "i40", DataType::Integer40, Access::ReadWrite, -2);
  od.add_var(0x2003, "r32", DataType::Real32, Access::ReadWrite, 1.5);
  od.add_var(0x2004, "r64", DataType::Real64, Access::ReadWrite, -0.25);
  od.add_var(0x2005, "u64", DataType::Unsigned64, Access::ReadWrite, 0xFEDCBA9876543210ull);
  od.add_var(0x2006, "bool", DataType::Boolean, Access::ReadWrite, 1);
  EXPECT_EQ(od.get<int>(0x2000), -3);
  EXPECT_EQ(od.entry(0x2000, 0)->value, (Bytes{0xFD}));
  EXPECT_EQ(od.get<std::uint32_t>(0x2001), 0xABCDEFu);
  EXPECT_EQ(od.entry(0x2001, 0)->size(), 3u);
  EXPECT_EQ(od.get<std::int64_t>(0x2002), -2);
  EXPECT_EQ(od.entry(0x2002, 0)->value, (Bytes{0xFE, 0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_FLOAT_EQ(od.get<float>(0x2003), 1.5f);
  EXPECT_DOUBLE_EQ(od.get<double>(0x2004), -0.25);
  EXPECT_EQ(od.get<std::uint64_t>(0x2005), 0xFEDCBA9876543210ull);
  EXPECT_TRUE(od.get<bool>(0x2006));
  od.set<std::int16_t>(0x2000, 0, -128);
  EXPECT_EQ(od.get<int>(0x2000), -128);
}

TEST(ObjectDictionary, LocateDistinguishesMissingObjectAndSubIndex) {
  auto od = vtest::make_generic_od();
  OdEntry* e = nullptr;
  EXPECT_EQ(od.locate(0x2FFF, 0, e), SdoAbort::NoObject);
  EXPECT_EQ(od.locate(0x1018, 9, e), SdoAbort::NoSubIndex);
  EXPECT_EQ(od.locate(0x1018, 1, e), SdoAbort::None);
  EXPECT_EQ(e->as<std::uint32_t>(), 0x12345678u);
}

TEST(ObjectDictionary, AccessRightsAndLimits) {
  auto od = vtest::make_generic_od();
  const Bytes two{0x01, 0x00};
  EXPECT_EQ(od.write(0x2003, 0, Bytes{1, 2, 3, 4}, Origin::Sdo), SdoAbort::ReadOnly);
  EXPECT_EQ(od.write(0x2005, 0, Bytes{1, 2, 3, 4}, Origin::Sdo), SdoAbort::ReadOnly);
  Bytes out;
  EXPECT_EQ(od.read(0x2004, 0, out, Origin::Sdo), SdoAbort::WriteOnly);
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, 101), Origin::Sdo), SdoAbort::ValueTooHigh);
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, -101), Origin::Sdo), SdoAbort::ValueTooLow);
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, 100), Origin::Sdo), SdoAbort::None);
  // A PDO cannot be refused: out-of-range values are clamped.
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, 30000), Origin::Pdo), SdoAbort::None);
  EXPECT_EQ(od.get<int>(0x2001), 100);
  // Devices may refuse writes to read-only entries with another code.
  od.access_aborts().write_read_only = SdoAbort::UnsupportedAccess;
  EXPECT_EQ(od.write(0x2003, 0, Bytes{1, 2, 3, 4}, Origin::Sdo), SdoAbort::UnsupportedAccess);
  // Internal writes bypass access rights.
  EXPECT_EQ(od.write(0x2003, 0, Bytes{1, 2, 3, 4}, Origin::Internal), SdoAbort::None);
  EXPECT_EQ(od.write(0x2000, 0, two, Origin::Sdo), SdoAbort::LengthTooHigh);
}

TEST(ObjectDictionary, StateChecksRunBeforeLimitsAndValueChecksAfter) {
  auto od = vtest::make_generic_od();
  std::vector<std::string> order;
  od.add_check(0x2001, 0, [&](const OdEntry&, std::span<std::uint8_t>, Origin) {
    order.push_back("value");
    return SdoAbort::None;
  });
  od.add_check(
      0x2001, 0,
      [&](const OdEntry&, std::span<std::uint8_t>, Origin) {
        order.push_back("state");
        return SdoAbort::DataDeviceState;
      },
      CheckStage::State);
  // Out of range AND wrong state: the state abort wins.
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, 500), Origin::Sdo), SdoAbort::DataDeviceState);
  EXPECT_EQ(order, (std::vector<std::string>{"state"}));
}

TEST(ObjectDictionary, TypedHooksSeeValuesAndObserversRunAfterCommit) {
  auto od = vtest::make_generic_od();
  int seen = 0, observed = 0;
  od.on_write<std::int16_t>(0x2001, 0, [&](std::int16_t v, Origin) {
    seen = v;
    return v == 13 ? SdoAbort::InvalidValue : SdoAbort::None;
  });
  od.after_write<std::int16_t>(0x2001, 0, [&](std::int16_t v, Origin) { observed = v; });
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, 13), Origin::Sdo), SdoAbort::InvalidValue);
  EXPECT_EQ(seen, 13);
  EXPECT_EQ(observed, 0);
  EXPECT_EQ(od.get<int>(0x2001), -5);
  EXPECT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, -7), Origin::Sdo), SdoAbort::None);
  EXPECT_EQ(observed, -7);
  // set() is the device's own write: no hooks.
  od.set<std::int16_t>(0x2001, 0, 55);
  EXPECT_EQ(observed, -7);
}

TEST(ObjectDictionary, NodeRelativeDefaults) {
  auto od = vtest::make_generic_od();
  od.reset_range(0x1000, 0x1FFF, 5);
  EXPECT_EQ(od.get<std::uint32_t>(0x1800, 1), 0x185u);
  EXPECT_EQ(od.get<std::uint32_t>(0x1014, 0), 0x85u);
  EXPECT_EQ(od.get<std::uint32_t>(0x1200, 2), 0x585u);
  od.reset_range(0x1000, 0x1FFF, 127);
  EXPECT_EQ(od.get<std::uint32_t>(0x1400, 1), 0x27Fu);
}

TEST(ObjectDictionary, ResizeValueExtendsSigned) {
  EXPECT_EQ(resize_value(DataType::Integer16, Bytes{0xFE}, 2), (Bytes{0xFE, 0xFF}));
  EXPECT_EQ(resize_value(DataType::Unsigned16, Bytes{0xFE}, 2), (Bytes{0xFE, 0x00}));
  EXPECT_EQ(resize_value(DataType::Integer32, Bytes{0x01, 0x02, 0x03, 0x04}, 2), (Bytes{0x01, 0x02}));
}
