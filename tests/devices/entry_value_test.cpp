// devices/entry_value.h: the inline reads and writes give exactly what OdEntry::as<T>() and
// encode_unsigned() give, for every integer type and width, sign bits included.
#include "devices/entry_value.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace devices {
namespace {

using canopen::Access;
using canopen::Bytes;
using canopen::DataType;

const std::vector<DataType> kTypes = {
    DataType::Boolean,   DataType::Integer8,   DataType::Integer16,  DataType::Integer24,  DataType::Integer32,
    DataType::Integer40, DataType::Integer48,  DataType::Integer56,  DataType::Integer64,  DataType::Unsigned8,
    DataType::Unsigned16, DataType::Unsigned24, DataType::Unsigned32, DataType::Unsigned40, DataType::Unsigned48,
    DataType::Unsigned56, DataType::Unsigned64};

const std::vector<std::uint64_t> kPatterns = {0,          1,          0x7F,       0x80,       0xFF,
                                              0x7FFF,     0x8000,     0xFFFF,     0x123456,   0x800000,
                                              0x7FFFFFFF, 0x80000000, 0xFFFFFFFF, 0x8000000000ull,
                                              0x0123456789ABCDEFull, 0x8000000000000000ull, ~std::uint64_t{0}};

template <typename T>
void expect_same_read(const canopen::OdEntry& e, const IntegerEntry& b) {
  EXPECT_EQ(b.as<T>(), e.as<T>()) << "type 0x" << std::hex << static_cast<int>(e.type) << " bytes " << e.value.size();
}

TEST(EntryValue, ReadsAsOdEntryAsDoes) {
  canopen::ObjectDictionary od;
  std::uint16_t index = 0x2000;
  for (DataType type : kTypes) {
    auto& e = od.add_var(index++, "v", type, Access::ReadWrite, Bytes(canopen::type_size(type), 0));
    const IntegerEntry b(&e);
    for (std::uint64_t p : kPatterns) {
      canopen::encode_unsigned(p, e.value);
      EXPECT_EQ(entry_bits(e), canopen::decode_unsigned(e.value));
      expect_same_read<std::int8_t>(e, b);
      expect_same_read<std::uint8_t>(e, b);
      expect_same_read<std::int16_t>(e, b);
      expect_same_read<std::uint16_t>(e, b);
      expect_same_read<std::int32_t>(e, b);
      expect_same_read<std::uint32_t>(e, b);
      expect_same_read<std::int64_t>(e, b);
      expect_same_read<std::uint64_t>(e, b);
    }
  }
}

TEST(EntryValue, RealEntriesTakeTheGenericPath) {
  canopen::ObjectDictionary od;
  auto& e32 = od.add_var<float>(0x2000, "r32", DataType::Real32, Access::ReadWrite, -12.75f);
  auto& e64 = od.add_var<double>(0x2001, "r64", DataType::Real64, Access::ReadWrite, 1e10);
  EXPECT_EQ(IntegerEntry(&e32).as<std::int32_t>(), e32.as<std::int32_t>());
  EXPECT_EQ(IntegerEntry(&e32).as<std::int32_t>(), -12);
  EXPECT_EQ(IntegerEntry(&e64).as<std::int64_t>(), e64.as<std::int64_t>());
}

TEST(EntryValue, StoresAsEncodeUnsignedDoes) {
  for (DataType type : kTypes) {
    const std::size_t n = canopen::type_size(type);
    for (std::uint64_t p : kPatterns) {
      canopen::OdEntry e;
      e.type = type;
      e.value = Bytes(n, 0xA5);
      Bytes expected(n, 0xA5);
      canopen::encode_unsigned(p, expected);
      store_entry_bits(e, p);
      EXPECT_EQ(e.value, expected) << "type 0x" << std::hex << static_cast<int>(type) << " value " << p;
    }
  }
  // Signed values are written in two's complement, truncated to the entry.
  canopen::OdEntry e;
  e.type = DataType::Integer16;
  e.value = Bytes(2, 0);
  store_entry_bits(e, static_cast<std::uint64_t>(std::int64_t{-2}));
  EXPECT_EQ(e.value, (Bytes{0xFE, 0xFF}));
  EXPECT_EQ(IntegerEntry(&e).as<std::int32_t>(), -2);
}

TEST(EntryValue, AnUnboundEntryReadsZero) {
  const IntegerEntry unbound;
  EXPECT_FALSE(unbound);
  EXPECT_EQ(unbound.as<std::int64_t>(), 0);
  EXPECT_EQ(IntegerEntry(nullptr).as<std::uint16_t>(), 0u);
}

TEST(EntryValue, AReplacedValueVectorIsReadAfresh) {
  // Writes and resets may assign a new vector; the bound entry holds the entry, not its bytes.
  canopen::ObjectDictionary od;
  auto& e = od.add_var<std::uint32_t>(0x2000, "v", DataType::Unsigned32, Access::ReadWrite, 7u);
  const IntegerEntry b(&e);
  e.assign<std::uint32_t>(0xDEADBEEFu);
  EXPECT_EQ(b.as<std::uint32_t>(), 0xDEADBEEFu);
  od.set<std::uint32_t>(0x2000, 0, 42u);
  EXPECT_EQ(b.as<std::uint32_t>(), 42u);
}

}  // namespace
}  // namespace devices
