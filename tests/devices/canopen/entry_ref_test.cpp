// The typed handle on an entry's value (devices/canopen/entry_ref.h) and the inline value store
// (stored_value.h): get() is OdEntry::as<T>() and set() is OdEntry::assign(T) for every width and
// sign, REAL32/REAL64 included; an SDO or RPDO write is what the handle reads next, a handle write
// is what an SDO upload and a TPDO carry; protocol writes still run their checks and observers.
#include "devices/canopen/entry_ref.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using namespace canopen;

namespace {

const std::vector<DataType> kIntegerTypes = {
    DataType::Boolean,    DataType::Integer8,   DataType::Integer16,  DataType::Integer24,  DataType::Integer32,
    DataType::Integer40,  DataType::Integer48,  DataType::Integer56,  DataType::Integer64,  DataType::Unsigned8,
    DataType::Unsigned16, DataType::Unsigned24, DataType::Unsigned32, DataType::Unsigned40, DataType::Unsigned48,
    DataType::Unsigned56, DataType::Unsigned64};

const std::vector<std::uint64_t> kPatterns = {0,          1,          0x7F,       0x80,           0xFF,
                                              0x7FFF,     0x8000,     0xFFFF,     0x123456,       0x800000,
                                              0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0x8000000000ull, 0x0123456789ABCDEFull,
                                              0x8000000000000000ull, ~std::uint64_t{0}};

std::string label(const OdEntry& e) {
  return std::string(type_name(e.type)) + " bytes " + std::to_string(e.value.size());
}

template <typename T>
void expect_reads_as_entry(OdEntry& e) {
  EXPECT_EQ(EntryRef<T>(e).get(), e.as<T>()) << label(e);
}

template <typename T>
void expect_writes_as_assign(const OdEntry& original, T v) {
  OdEntry handle_written = original, assigned = original;
  EntryRef<T>(handle_written).set(v);
  assigned.assign(v);
  EXPECT_EQ(handle_written.value, assigned.value.bytes()) << label(original) << " value " << +v;
}

ObjectDictionary every_width() {
  ObjectDictionary od;
  std::uint16_t index = 0x2000;
  for (DataType type : kIntegerTypes) od.add_var(index++, "v", type, Access::ReadWrite, Bytes(type_size(type), 0));
  return od;
}

}  // namespace

TEST(EntryRef, ReadsEveryWidthAndSignAsTheEntryDoes) {
  ObjectDictionary od = every_width();
  for (auto& [index, object] : od.objects()) {
    OdEntry& e = *od.entry(index, 0);
    for (std::uint64_t p : kPatterns) {
      encode_unsigned(p, e.value);
      expect_reads_as_entry<std::int8_t>(e);
      expect_reads_as_entry<std::uint8_t>(e);
      expect_reads_as_entry<std::int16_t>(e);
      expect_reads_as_entry<std::uint16_t>(e);
      expect_reads_as_entry<std::int32_t>(e);
      expect_reads_as_entry<std::uint32_t>(e);
      expect_reads_as_entry<std::int64_t>(e);
      expect_reads_as_entry<std::uint64_t>(e);
      expect_reads_as_entry<double>(e);
      expect_reads_as_entry<bool>(e);
    }
  }
}

TEST(EntryRef, SignExtendsFromTheEntryWidth) {
  ObjectDictionary od;
  od.add_entry(0x2100, 1, "i24", DataType::Integer24, Access::ReadWrite, Bytes{0xFE, 0xFF, 0xFF});
  od.add_var(0x2101, "i8", DataType::Integer8, Access::ReadWrite, Bytes{0x80});
  od.add_var(0x2102, "u8", DataType::Unsigned8, Access::ReadWrite, Bytes{0x80});
  od.add_var(0x2103, "i40", DataType::Integer40, Access::ReadWrite, Bytes{0, 0, 0, 0, 0x80});
  EXPECT_EQ(EntryRef<std::int32_t>(od, 0x2100, 1).get(), -2);
  EXPECT_EQ(EntryRef<std::int64_t>(od, 0x2101, 0).get(), -128);
  EXPECT_EQ(EntryRef<std::int64_t>(od, 0x2102, 0).get(), 128);  // unsigned: no sign
  EXPECT_EQ(EntryRef<std::int64_t>(od, 0x2103, 0).get(), -(std::int64_t{1} << 39));
  EXPECT_EQ(EntryRef<std::uint16_t>(od, 0x2101, 0).get(), 0xFF80u);  // sign-extended, then cast
}

TEST(EntryRef, WritesEveryWidthAsAssignDoes) {
  ObjectDictionary od = every_width();
  for (auto& [index, object] : od.objects()) {
    const OdEntry& e = *od.entry(index, 0);
    for (std::uint64_t p : kPatterns) {
      expect_writes_as_assign<std::uint64_t>(e, p);
      expect_writes_as_assign<std::int64_t>(e, static_cast<std::int64_t>(p));
      expect_writes_as_assign<std::int32_t>(e, static_cast<std::int32_t>(p));
      expect_writes_as_assign<std::uint16_t>(e, static_cast<std::uint16_t>(p));
      expect_writes_as_assign<std::int8_t>(e, static_cast<std::int8_t>(p));
      expect_writes_as_assign<bool>(e, (p & 1) != 0);
    }
    expect_writes_as_assign<double>(e, -3.75);
  }
}

TEST(EntryRef, Real32AndReal64) {
  ObjectDictionary od;
  od.add_var<float>(0x2000, "r32", DataType::Real32, Access::ReadWrite, -12.75f);
  od.add_var<double>(0x2001, "r64", DataType::Real64, Access::ReadWrite, 1e10);
  const EntryRef<float> r32(od, 0x2000, 0);
  const EntryRef<double> r64(od, 0x2001, 0);
  EXPECT_EQ(r32.get(), -12.75f);
  EXPECT_EQ(r64.get(), 1e10);
  EXPECT_EQ(EntryRef<std::int32_t>(od, 0x2000, 0).get(), -12);  // converted, as as<int32_t>()
  EXPECT_EQ(EntryRef<double>(od, 0x2000, 0).get(), -12.75);
  r32.set(0.1f);
  float f = 0.1f;
  Bytes expected(4);
  std::memcpy(expected.data(), &f, 4);
  EXPECT_EQ(od.entry(0x2000, 0)->value, expected);
  EntryRef<std::int16_t>(od, 0x2001, 0).set(-7);  // an integer into a REAL64: converted
  EXPECT_EQ(r64.get(), -7.0);
  for (float v : {0.0f, -0.0f, 1.5f, std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min()})
    expect_writes_as_assign<float>(*od.entry(0x2000, 0), v);
}

TEST(EntryRef, SetRoundedRoundsAndClamps) {
  ObjectDictionary od;
  od.add_var(0x2002, "temperature", DataType::Integer16, Access::ReadOnly, 0);
  const EntryRef<std::int64_t> t(od, 0x2002, 0);
  t.set_rounded(24.5, -55, 150);
  EXPECT_EQ(od.get<std::int16_t>(0x2002), 25);  // half away from zero
  t.set_rounded(-24.5, -55, 150);
  EXPECT_EQ(od.get<std::int16_t>(0x2002), -25);
  t.set_rounded(1000, -55, 150);
  EXPECT_EQ(od.get<std::int16_t>(0x2002), 150);
  t.set_rounded(-1000, -55, 150);
  EXPECT_EQ(od.get<std::int16_t>(0x2002), -55);
  t.set_rounded(-0.4, -55, 150);
  EXPECT_EQ(od.entry(0x2002, 0)->value, (Bytes{0, 0}));
}

TEST(EntryRef, SeesWhatSdoAndRpdoWrite) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  const EntryRef<std::uint16_t> out(h.node().od(), 0x6000, 0);
  const EntryRef<std::int32_t> command(h.node().od(), 0x6001, 0);
  ASSERT_EQ(h.write(0x6000, 0, 0xBEEF, 2), 0u);
  EXPECT_EQ(out.get(), 0xBEEF);
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.send(0x205, {0xFE, 0xFF, 0xFF, 0xFF, 0x34, 0x12});  // RPDO1: 6001h = −2, 6000h = 0x1234
  h.run_ticks(1);
  EXPECT_EQ(command.get(), -2);
  EXPECT_EQ(out.get(), 0x1234);
}

TEST(EntryRef, AHandleWriteIsWhatSdoUploadAndTpdoCarry) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  const EntryRef<std::uint16_t> out(h.node().od(), 0x6000, 0);
  const EntryRef<std::int32_t> command(h.node().od(), 0x6001, 0);
  out.set(0x0A0B);
  command.set(-3);
  EXPECT_EQ(h.read(0x6000, 0), (std::vector<std::uint8_t>{0x0B, 0x0A}));
  EXPECT_EQ(h.read(0x6001, 0), (std::vector<std::uint8_t>{0xFD, 0xFF, 0xFF, 0xFF}));
  h.nmt(0x01, 5);
  h.run_ticks(1);
  h.take();
  out.set(0x0102);
  h.run_ticks(1);
  EXPECT_EQ(h.take(), vtest::Frames{vtest::Frame(0x185, {0x02, 0x01, 0x55})});  // TPDO1: 6000h + 6002h
}

TEST(EntryRef, ProtocolWritesRunTheirHooksAndTheHandleReadsTheResult) {
  ObjectDictionary od;
  od.add_var(0x2000, "limited", DataType::Integer16, Access::ReadWrite, 0);
  od.entry(0x2000, 0)->high_limit = ObjectDictionary::encode(DataType::Integer16, 100);
  std::vector<std::int16_t> seen;
  int checks = 0;
  od.on_write<std::int16_t>(0x2000, 0, [&checks](std::int16_t, Origin) {
    ++checks;
    return SdoAbort::None;
  });
  od.after_write<std::int16_t>(0x2000, 0, [&seen](std::int16_t v, Origin) { seen.push_back(v); });
  const EntryRef<std::int16_t> h(od, 0x2000, 0);
  ASSERT_EQ(od.write(0x2000, 0, ObjectDictionary::encode(DataType::Integer16, -40), Origin::Sdo), SdoAbort::None);
  EXPECT_EQ(h.get(), -40);
  EXPECT_EQ(od.write(0x2000, 0, ObjectDictionary::encode(DataType::Integer16, 500), Origin::Sdo), SdoAbort::ValueTooHigh);
  EXPECT_EQ(h.get(), -40);  // refused: unchanged
  ASSERT_EQ(od.write(0x2000, 0, ObjectDictionary::encode(DataType::Integer16, 500), Origin::Pdo), SdoAbort::None);
  EXPECT_EQ(h.get(), 100);  // an RPDO value is clamped
  EXPECT_EQ(checks, 2);
  EXPECT_EQ(seen, (std::vector<std::int16_t>{-40, 100}));
  h.set(7);  // a device publishing its own value: no checks, no observers
  EXPECT_EQ(checks, 2);
  EXPECT_EQ(seen.size(), 2u);
  EXPECT_EQ(od.get<std::int16_t>(0x2000), 7);
}

TEST(EntryRef, RefusesAStringOrAMissingEntryAndAnOptionalOneReadsZero) {
  ObjectDictionary od;
  od.add_var(0x1008, "name", DataType::VisibleString, Access::Const, std::string("vplant"));
  od.add_var(0x2000, "u16", DataType::Unsigned16, Access::ReadWrite, 500);
  EXPECT_THROW(EntryRef<std::uint32_t>(od, 0x1008, 0), std::invalid_argument);
  EXPECT_THROW(EntryRef<std::uint8_t>(od, 0x2FFF, 0), std::invalid_argument);
  try {
    EntryRef<std::uint32_t>(od, 0x1008, 0);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("0x1008:00 is VISIBLE_STRING"), std::string::npos) << e.what();
  }
  const auto absent = EntryRef<std::uint16_t>::optional(od, 0x2FFF, 0);
  EXPECT_FALSE(absent);
  EXPECT_EQ(absent.get(), 0u);
  EXPECT_FALSE(EntryRef<std::int64_t>::optional(nullptr).bound());
  const auto present = EntryRef<std::uint16_t>::optional(od, 0x2000, 0);
  ASSERT_TRUE(present);
  EXPECT_EQ(present.get(), 500);
  EXPECT_EQ(&present.entry(), od.entry(0x2000, 0));
}

TEST(EntryRef, FollowsAValueResizedOrReset) {
  ObjectDictionary od;
  auto& e = od.add_var<std::uint32_t>(0x2000, "v", DataType::Unsigned32, Access::ReadWrite, 7u);
  const EntryRef<std::uint32_t> h(e);
  od.set_bytes(0x2000, 0, Bytes{0x01, 0x02});  // a device may store fewer bytes: read as as<>()
  EXPECT_EQ(h.get(), e.as<std::uint32_t>());
  EXPECT_EQ(h.get(), 0x0201u);
  h.set(0xDEADBEEFu);  // and a write restores the type's size, as assign() does
  EXPECT_EQ(e.value, (Bytes{0xEF, 0xBE, 0xAD, 0xDE}));
  e.reset_to_default(1);
  EXPECT_EQ(h.get(), 7u);
}

TEST(StoredValue, ScalarsInlineLongValuesOnTheHeap) {
  ObjectDictionary od;
  auto& u64 = od.add_var<std::uint64_t>(0x2000, "u64", DataType::Unsigned64, Access::ReadWrite, 0x0102030405060708u);
  auto& text = od.add_var(0x2001, "text", DataType::VisibleString, Access::ReadWrite, std::string("a longer string"));
  EXPECT_TRUE(u64.value.is_inline());
  EXPECT_EQ(u64.value.data(), u64.value.cell());
  EXPECT_EQ(u64.value, (Bytes{8, 7, 6, 5, 4, 3, 2, 1}));
  EXPECT_FALSE(text.value.is_inline());
  EXPECT_EQ(od.get_string(0x2001), "a longer string");
  ASSERT_EQ(od.write(0x2001, 0, Bytes{'o', 'k'}, Origin::Sdo), SdoAbort::None);  // shrinks into the cell
  EXPECT_TRUE(text.value.is_inline());
  EXPECT_EQ(od.get_string(0x2001), "ok");
  const std::string longer = "longer again, past the cell";
  ASSERT_EQ(od.write(0x2001, 0, Bytes(longer.begin(), longer.end()), Origin::Sdo), SdoAbort::None);
  EXPECT_EQ(od.get_string(0x2001), longer);
  Bytes read;
  ASSERT_EQ(od.read(0x2001, 0, read, Origin::Sdo), SdoAbort::None);
  EXPECT_EQ(read, Bytes(longer.begin(), longer.end()));
}
