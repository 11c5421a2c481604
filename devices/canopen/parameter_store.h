// Non-volatile memory of one node: the values "store parameters" (0x1010) saved. Kept in memory
// (so it survives NMT resets and power cycles within a run) and, when a path is set, in a file
// that is replaced atomically (write temp, fsync, rename, fsync directory): a kill -9 at any
// moment leaves either the old or the new set, never a torn one.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "devices/canopen/object_dictionary.h"

namespace canopen {

class ParameterStore {
 public:
  struct Value {
    bool node_relative = false;  ///< stored as "$NODEID+x": the node-ID is added when loaded
    Bytes bytes;
    int line = 0;  ///< the line of the store file it was read from (0: put by the program)
  };
  using Key = std::pair<std::uint16_t, std::uint8_t>;

  explicit ParameterStore(std::string path = {}) : path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  /// "file:line" of a value read from the file ("file" alone for one put by the program).
  std::string where(const Value& v) const;
  void set_path(std::string path) { path_ = std::move(path); }

  /// Reads the file (a missing file is an empty store; without a path the values in memory
  /// are kept, so they survive power cycles within a run). Anything but a regular file of at
  /// most sim::kMaxInputFileBytes is refused ("file: reason"); a malformed line is reported as
  /// "file:line: reason" (its bytes escaped) and the store stays empty (never a half-read set).
  /// The values are not checked against a dictionary here: StoreRestore does that.
  bool load(std::string& error);
  /// Writes the file atomically. Without a path it only keeps the values in memory.
  bool save(std::string& error) const;

  const std::map<Key, Value>& values() const { return values_; }
  const Value* find(std::uint16_t index, std::uint8_t sub) const;
  void put(std::uint16_t index, std::uint8_t sub, Value v) { values_[{index, sub}] = std::move(v); }
  void erase_range(std::uint16_t first, std::uint16_t last);
  void clear() { values_.clear(); }
  /// Injected failure of the memory (fault injection): "store parameters" and the LSS "store
  /// configuration" fail (StoreRestore, LssSlave).
  void set_failing(bool failing) { failing_ = failing; }
  bool failing() const { return failing_; }

 private:
  std::string path_;
  std::map<Key, Value> values_;
  bool failing_ = false;
};

}  // namespace canopen
