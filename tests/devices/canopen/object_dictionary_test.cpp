#include "devices/canopen/object_dictionary.h"

#include <gtest/gtest.h>

#include <array>

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

TEST(ObjectDictionary, LookupsStayRightAcrossAdditionRemovalAndCopies) {
  ObjectDictionary od;
  od.add_var(0x2000, "a", DataType::Unsigned16, Access::ReadWrite, ObjectDictionary::encode(DataType::Unsigned16, 7));
  EXPECT_EQ(od.entry(0x2000, 1), nullptr);
  EXPECT_EQ(od.entry(0x2100, 0), nullptr);
  od.add_entry(0x2000, 1, "b", DataType::Unsigned8, Access::ReadWrite, ObjectDictionary::encode(DataType::Unsigned8, 9));
  ASSERT_NE(od.entry(0x2000, 1), nullptr);  // found after it was added
  EXPECT_EQ(od.get<int>(0x2000, 1), 9);
  EXPECT_EQ(od.entry(0x2000, 0), &od.object(0x2000)->entries.at(0));

  OdEntry copied = *od.entry(0x2000, 1);
  copied.sub = 2;
  od.add_entry(copied);
  ASSERT_NE(od.entry(0x2000, 2), nullptr);
  od.add_var(0x2100, "c", DataType::Unsigned8, Access::ReadWrite, ObjectDictionary::encode(DataType::Unsigned8, 1));
  EXPECT_NE(od.entry(0x2100, 0), nullptr);

  od.remove_entry(0x2000, 1);
  EXPECT_EQ(od.entry(0x2000, 1), nullptr);
  od.remove_object(0x2100);
  EXPECT_EQ(od.entry(0x2100, 0), nullptr);

  ObjectDictionary copy = od;
  copy.set<int>(0x2000, 0, 11);
  EXPECT_EQ(copy.entry(0x2000, 0), &copy.object(0x2000)->entries.at(0));  // its own entry
  EXPECT_EQ(od.get<int>(0x2000, 0), 7);
  od = copy;
  EXPECT_EQ(od.get<int>(0x2000, 0), 11);
  EXPECT_EQ(od.entry(0x2000, 0), &od.object(0x2000)->entries.at(0));
}

TEST(ObjectDictionary, LayoutStampChangesWithTheObjectSetNotWithValues) {
  ObjectDictionary od;
  od.add_var(0x2000, "a", DataType::Unsigned16, Access::ReadWrite, 7);
  auto stamp = od.layout();
  od.set<int>(0x2000, 0, 8);
  EXPECT_EQ(od.write(0x2000, 0, ObjectDictionary::encode(DataType::Unsigned16, 9), Origin::Sdo), SdoAbort::None);
  od.add_object(0x2000, "again", ObjectCode::Var);  // already there: nothing changes
  EXPECT_EQ(od.layout(), stamp);

  auto changed = [&] {
    const bool c = od.layout() != stamp;
    stamp = od.layout();
    return c;
  };
  od.add_entry(0x2000, 1, "b", DataType::Unsigned8, Access::ReadWrite, 1);
  EXPECT_TRUE(changed());
  od.add_entry(0x2000, 1, "b wider", DataType::Unsigned32, Access::ReadWrite, 1u);  // replaced in place
  EXPECT_TRUE(changed());
  od.add_entry(*od.entry(0x2000, 1));
  EXPECT_TRUE(changed());
  od.remove_entry(0x2000, 1);
  EXPECT_TRUE(changed());
  od.add_object(0x2100, "c", ObjectCode::Record);
  EXPECT_TRUE(changed());
  od.remove_object(0x2100);
  EXPECT_TRUE(changed());
  const ObjectDictionary copy = od;
  EXPECT_NE(copy.layout(), od.layout());  // a copy's entries are others: never mistaken for these
  od = copy;
  EXPECT_TRUE(changed());
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

TEST(ObjectDictionary, CodecsHandleEveryWidthLittleEndianWithSignExtension) {
  const Bytes b{0x81, 0x82, 0x83, 0x84, 0x85, 0x86, 0x87, 0x88, 0x89};
  const std::span<const std::uint8_t> s(b);
  EXPECT_EQ(decode_unsigned(s.first(0)), 0u);
  EXPECT_EQ(decode_unsigned(s.first(1)), 0x81u);
  EXPECT_EQ(decode_unsigned(s.first(2)), 0x8281u);
  EXPECT_EQ(decode_unsigned(s.first(3)), 0x838281u);
  EXPECT_EQ(decode_unsigned(s.first(4)), 0x84838281u);
  EXPECT_EQ(decode_unsigned(s.first(6)), 0x868584838281u);
  EXPECT_EQ(decode_unsigned(s.first(8)), 0x8887868584838281u);
  EXPECT_EQ(decode_unsigned(s), 0x8887868584838281u);  // beyond 8 bytes: the first 8
  EXPECT_EQ(decode_signed(s.first(0)), 0);
  EXPECT_EQ(decode_signed(s.first(1)), -127);
  EXPECT_EQ(decode_signed(s.first(2)), static_cast<std::int16_t>(0x8281));
  EXPECT_EQ(decode_signed(s.first(3)), 0x838281 - 0x1000000);
  EXPECT_EQ(decode_signed(s.first(4)), static_cast<std::int32_t>(0x84838281u));
  EXPECT_EQ(decode_signed(s.first(5)), static_cast<std::int64_t>(0x8584838281u) - (std::int64_t{1} << 40));
  EXPECT_EQ(decode_signed(s.first(8)), static_cast<std::int64_t>(0x8887868584838281u));
  EXPECT_EQ(decode_signed(Bytes{0x7F, 0x00, 0x00}), 0x7F);

  for (std::size_t n : {1u, 2u, 3u, 4u, 5u, 7u, 8u, 10u}) {
    Bytes out(n, 0xEE);
    encode_unsigned(0x0807060504030201u, out);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(out[i], i < 8 ? i + 1 : 0) << n << " bytes, byte " << i;
  }
  EXPECT_EQ(encoded_size<std::int16_t>(DataType::Unsigned32), 4u);
  EXPECT_EQ(encoded_size<std::int16_t>(DataType::Domain), 2u);
  std::array<std::uint8_t, 4> real{};
  encode_into(DataType::Real32, 2, std::span<std::uint8_t>(real));
  EXPECT_EQ(value_as<double>(DataType::Real32, real), 2.0);
  std::array<std::uint8_t, 2> i16{};
  encode_into(DataType::Integer16, -2.0, std::span<std::uint8_t>(i16));
  EXPECT_EQ(value_as<int>(DataType::Integer16, i16), -2);
  EXPECT_EQ(value_as<int>(DataType::Unsigned16, i16), 0xFFFE);
}
