// The object dictionary's lookup cache: hits return the map's entries, cached misses are
// forgotten when entries are added, and removal and copies never leave a pointer to a destroyed
// or foreign entry.
#include <gtest/gtest.h>

#include "devices/canopen/entry_cache.h"
#include "devices/canopen/object_dictionary.h"

using namespace canopen;

TEST(EntryCache, GrowsAndFindsEveryKey) {
  EntryCache cache;
  std::vector<OdEntry> entries(3000);
  for (std::size_t i = 0; i < entries.size(); ++i)
    cache.insert(EntryCache::key(static_cast<std::uint16_t>(0x2000 + i / 7), static_cast<std::uint8_t>(i % 7)), &entries[i]);
  EXPECT_EQ(cache.size(), entries.size());
  OdEntry* found = nullptr;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    ASSERT_TRUE(cache.find(EntryCache::key(static_cast<std::uint16_t>(0x2000 + i / 7), static_cast<std::uint8_t>(i % 7)), found));
    EXPECT_EQ(found, &entries[i]);
  }
  EXPECT_FALSE(cache.find(EntryCache::key(0x1000, 0), found));
  EXPECT_FALSE(cache.find(EntryCache::key(0xFFFF, 0xFF), found));
  cache.insert(EntryCache::key(0x1000, 0), nullptr);  // a known miss
  ASSERT_TRUE(cache.find(EntryCache::key(0x1000, 0), found));
  EXPECT_EQ(found, nullptr);
  cache.clear();
  EXPECT_FALSE(cache.find(EntryCache::key(0x2000, 0), found));
}

TEST(EntryCache, DictionaryLookupsStayRightAcrossRemovalAndCopies) {
  ObjectDictionary od;
  od.add_var(0x2000, "a", DataType::Unsigned16, Access::ReadWrite, ObjectDictionary::encode(DataType::Unsigned16, 7));
  EXPECT_EQ(od.entry(0x2000, 1), nullptr);  // a cached miss
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
  EXPECT_NE(od.entry(0x2100, 0), nullptr);  // the earlier miss is forgotten

  od.remove_entry(0x2000, 1);
  EXPECT_EQ(od.entry(0x2000, 1), nullptr);  // not the removed entry's stale address
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
