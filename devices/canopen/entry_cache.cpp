#include "devices/canopen/entry_cache.h"

namespace canopen {

void EntryCache::insert(std::uint32_t key, OdEntry* entry) {
  if ((used_ + 1) * 2 > slots_.size()) grow();  // load factor ≤ 1/2 keeps probes short
  for (std::size_t i = hash(key);; i = (i + 1) & mask_) {
    Slot& s = slots_[i];
    if (s.key == key) {
      s.entry = entry;
      return;
    }
    if (s.key == kEmpty) {
      s = Slot{key, entry};
      ++used_;
      return;
    }
  }
}

void EntryCache::grow() {
  std::vector<Slot> old = std::move(slots_);
  slots_.assign(old.empty() ? 64 : old.size() * 2, Slot{});
  mask_ = slots_.size() - 1;
  used_ = 0;
  for (const Slot& s : old)
    if (s.key != kEmpty) insert(s.key, s.entry);
}

}  // namespace canopen
