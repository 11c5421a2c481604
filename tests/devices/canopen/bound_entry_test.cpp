// Typed bound entries: they read and write the entry's bytes, so a value written by SDO is what
// the binding reads, and a value the binding writes is what SDO reads, byte for byte as set<T>()
// would have stored it; a binding of the wrong type or to a missing entry is refused when made.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "devices/canopen/bound_entry.h"
#include "devices/canopen/object_dictionary.h"

using namespace canopen;

namespace {

ObjectDictionary make_od() {
  ObjectDictionary od;
  od.add_var(0x2000, "u8", DataType::Unsigned8, Access::ReadWrite, 3);
  od.add_var(0x2001, "i16", DataType::Integer16, Access::ReadWrite, -5);
  od.add_var(0x2002, "u32", DataType::Unsigned32, Access::ReadWrite, 0x12345678u);
  od.add_var(0x2003, "i32", DataType::Integer32, Access::ReadWrite, -100000);
  od.add_var(0x2004, "r32", DataType::Real32, Access::ReadWrite, 1.5);
  od.add_var(0x2005, "r64", DataType::Real64, Access::ReadWrite, -2.25);
  od.add_var(0x2006, "bool", DataType::Boolean, Access::ReadWrite, 1);
  od.add_var(0x2007, "i8", DataType::Integer8, Access::ReadWrite, -1);
  od.add_var(0x2008, "u16", DataType::Unsigned16, Access::ReadWrite, 500);
  od.add_var(0x2009, "i64", DataType::Integer64, Access::ReadWrite, -7);
  od.add_var(0x200A, "u64", DataType::Unsigned64, Access::ReadWrite, 7);
  od.add_entry(0x2100, 2, "i24", DataType::Integer24, Access::ReadWrite, -2);
  return od;
}

}  // namespace

TEST(BoundEntry, ReadsTheDefaultsAsTheEntryDoes) {
  ObjectDictionary od = make_od();
  EXPECT_EQ(BoundEntry<std::uint8_t>(od, 0x2000, 0).get(), 3);
  EXPECT_EQ(BoundEntry<std::int16_t>(od, 0x2001, 0).get(), -5);
  EXPECT_EQ(BoundEntry<std::uint32_t>(od, 0x2002, 0).get(), 0x12345678u);
  EXPECT_EQ(BoundEntry<std::int32_t>(od, 0x2003, 0).get(), -100000);
  EXPECT_EQ(BoundEntry<float>(od, 0x2004, 0).get(), 1.5f);
  EXPECT_EQ(BoundEntry<double>(od, 0x2005, 0).get(), -2.25);
  EXPECT_TRUE(BoundEntry<bool>(od, 0x2006, 0).get());
  EXPECT_EQ(BoundEntry<std::uint8_t>(od, 0x2006, 0).get(), 1);
  EXPECT_EQ(BoundEntry<std::int8_t>(od, 0x2007, 0).get(), -1);
  EXPECT_EQ(BoundEntry<std::uint16_t>(od, 0x2008, 0).get(), 500);
  EXPECT_EQ(BoundEntry<std::int64_t>(od, 0x2009, 0).get(), -7);
  EXPECT_EQ(BoundEntry<std::uint64_t>(od, 0x200A, 0).get(), 7u);
}

TEST(BoundEntry, SeesWhatSdoWrites) {
  ObjectDictionary od = make_od();
  const BoundEntry<std::int16_t> i16(od, 0x2001, 0);
  const BoundEntry<float> r32(od, 0x2004, 0);
  const BoundEntry<std::uint32_t> u32(od, 0x2002, 0);
  ASSERT_EQ(od.write(0x2001, 0, ObjectDictionary::encode(DataType::Integer16, -1234), Origin::Sdo), SdoAbort::None);
  ASSERT_EQ(od.write(0x2004, 0, ObjectDictionary::encode(DataType::Real32, -0.125), Origin::Sdo), SdoAbort::None);
  ASSERT_EQ(od.write(0x2002, 0, Bytes{0x01, 0x02, 0x03, 0x84}, Origin::Pdo), SdoAbort::None);
  EXPECT_EQ(i16.get(), -1234);
  EXPECT_EQ(r32.get(), -0.125f);
  EXPECT_EQ(u32.get(), 0x84030201u);
}

TEST(BoundEntry, WritesTheBytesSdoReadsAndSetWouldStore) {
  ObjectDictionary od = make_od(), reference = make_od();
  BoundEntry<std::int16_t>(od, 0x2001, 0).set(-2);
  reference.set<std::int16_t>(0x2001, 0, -2);
  BoundEntry<std::uint32_t>(od, 0x2002, 0).set(0xA1B2C3D4u);
  reference.set<std::uint32_t>(0x2002, 0, 0xA1B2C3D4u);
  BoundEntry<std::int32_t>(od, 0x2003, 0).set(std::numeric_limits<std::int32_t>::min());
  reference.set<std::int32_t>(0x2003, 0, std::numeric_limits<std::int32_t>::min());
  BoundEntry<float>(od, 0x2004, 0).set(3.75f);
  reference.set<float>(0x2004, 0, 3.75f);
  BoundEntry<double>(od, 0x2005, 0).set(-1e-300);
  reference.set<double>(0x2005, 0, -1e-300);
  BoundEntry<bool>(od, 0x2006, 0).set(false);
  reference.set<bool>(0x2006, 0, false);
  BoundEntry<std::int8_t>(od, 0x2007, 0).set(-128);
  reference.set<std::int8_t>(0x2007, 0, -128);
  BoundEntry<std::uint64_t>(od, 0x200A, 0).set(0x0102030405060708u);
  reference.set<std::uint64_t>(0x200A, 0, 0x0102030405060708u);

  EXPECT_EQ(od.get<std::uint32_t>(0x2002, 0), 0xA1B2C3D4u);
  for (std::uint16_t index = 0x2000; index <= 0x200A; ++index) {
    Bytes bound_bytes, set_bytes;
    ASSERT_EQ(od.read(index, 0, bound_bytes, Origin::Sdo), SdoAbort::None);
    ASSERT_EQ(reference.read(index, 0, set_bytes, Origin::Sdo), SdoAbort::None);
    EXPECT_EQ(bound_bytes, set_bytes) << "index " << index;
  }
  Bytes bytes;
  ASSERT_EQ(od.read(0x2002, 0, bytes, Origin::Sdo), SdoAbort::None);
  EXPECT_EQ(bytes, (Bytes{0xD4, 0xC3, 0xB2, 0xA1}));
}

TEST(BoundEntry, RefusesAWrongTypeOrAMissingEntryWhenBound) {
  ObjectDictionary od = make_od();
  EXPECT_THROW(BoundEntry<std::uint16_t>(od, 0x2001, 0), std::invalid_argument);  // INTEGER16
  EXPECT_THROW(BoundEntry<std::int32_t>(od, 0x2002, 0), std::invalid_argument);   // UNSIGNED32
  EXPECT_THROW(BoundEntry<double>(od, 0x2004, 0), std::invalid_argument);         // REAL32
  EXPECT_THROW(BoundEntry<std::int8_t>(od, 0x2006, 0), std::invalid_argument);    // BOOLEAN
  EXPECT_THROW(BoundEntry<std::int32_t>(od, 0x2100, 2), std::invalid_argument);   // INTEGER24
  EXPECT_THROW(BoundEntry<std::uint8_t>(od, 0x2FFF, 0), std::invalid_argument);   // absent
  EXPECT_THROW(BoundEntry<std::int8_t>::optional(od, 0x2000, 0), std::invalid_argument);
  try {
    BoundEntry<std::uint16_t>(od, 0x2001, 0);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0x2001:00 is INTEGER16"), std::string::npos) << e.what();
  }
}

TEST(BoundEntry, OptionalBindingOfAnAbsentEntryIsUnbound) {
  ObjectDictionary od = make_od();
  const auto absent = BoundEntry<std::uint16_t>::optional(od, 0x2FFF, 0);
  EXPECT_FALSE(absent.bound());
  const auto present = BoundEntry<std::uint16_t>::optional(od, 0x2008, 0);
  ASSERT_TRUE(present);
  EXPECT_EQ(present.get(), 500);
  EXPECT_EQ(&present.entry(), od.entry(0x2008, 0));
}
