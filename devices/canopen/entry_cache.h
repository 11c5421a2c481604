// A lookup cache (index, sub-index) → entry for the object dictionary. Devices and the PDO/SDO
// paths look entries up every tick and every frame; a std::map walk of two levels was the largest
// single cost of a simulated tick (13 % in scenario_bench). Filled lazily on the first lookup of
// an entry, open addressing with linear probing, no allocation once warm. Misses are cached too
// (the PDO service asks every tick for sub-indices a product does not have), so the dictionary
// clears the cache whenever an entry or object is added or removed. A copy starts empty (its
// pointers would point into the source dictionary).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace canopen {

struct OdEntry;

class EntryCache {
 public:
  EntryCache() = default;
  EntryCache(const EntryCache&) {}
  EntryCache& operator=(const EntryCache&) {
    clear();
    return *this;
  }

  static constexpr std::uint32_t key(std::uint16_t index, std::uint8_t sub) {
    return static_cast<std::uint32_t>(index) << 8 | sub;
  }

  /// True when `key` is cached; `out` is then its entry, or nullptr for a known miss.
  bool find(std::uint32_t key, OdEntry*& out) const {
    if (slots_.empty()) return false;
    for (std::size_t i = hash(key);; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.key == key) {
        out = s.entry;
        return true;
      }
      if (s.key == kEmpty) return false;
    }
  }
  /// Caches `entry` (nullptr: a miss) under `key`.
  void insert(std::uint32_t key, OdEntry* entry);
  void clear() {
    slots_.clear();
    used_ = 0;
    mask_ = 0;
  }
  std::size_t size() const { return used_; }

 private:
  static constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;  // no (index, sub) has this key
  struct Slot {
    std::uint32_t key = kEmpty;
    OdEntry* entry = nullptr;
  };
  std::size_t hash(std::uint32_t key) const { return (key * 0x9E3779B1u >> 7) & mask_; }
  void grow();

  std::vector<Slot> slots_;
  std::size_t used_ = 0;
  std::size_t mask_ = 0;
};

}  // namespace canopen
