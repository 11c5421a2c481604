// Store parameters (0x1010) and restore default parameters (0x1011), CiA 301 §7.5.2.13/14:
// signature "save"/"load", groups by sub-index, restored defaults effective after the next reset.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/parameter_store.h"
#include "devices/canopen/service_links.h"

namespace canopen {

class StoreRestore {
 public:
  static constexpr std::uint32_t kSaveSignature = 0x65766173;  // "save"
  static constexpr std::uint32_t kLoadSignature = 0x64616F6C;  // "load"

  /// `status`: node-ID (node-relative values) and time; `node_name` names the node in log lines;
  /// `silence`: the node is busy saving (StorePolicy::busy_time).
  StoreRestore(ObjectDictionary& od, const StorePolicy& policy, const NodeStatus& status, const std::string& node_name,
               SilenceRequest& silence);
  void bind_objects();

  /// Power-on: reads non-volatile memory (the file); pending restores are forgotten.
  bool power_on(std::string& error);
  /// Resets [first, last] to defaults and applies the stored values (unless a restore is pending
  /// for their group).
  void load_area(std::uint16_t first, std::uint16_t last);

  /// Saves group `sub` of 0x1010 now (also usable by devices that auto-save an object).
  SdoAbort save_group(std::uint8_t sub);
  /// Saves one entry immediately (objects a manual says are stored on write).
  SdoAbort save_entry(std::uint16_t index, std::uint8_t sub);
  SdoAbort restore_group(std::uint8_t sub);

  ParameterStore& memory() { return store_; }
  /// Keys the device itself saves and reads: a read-only entry (e.g. a position offset saved
  /// with save_entry), whose stored value loads although an SDO download could not write it, or
  /// a private cell that is no dictionary entry (e.g. characteristic points), left to the device.
  /// Stored values for other read-only, constant or missing entries are refused and reported.
  void allow_device_stored(std::uint16_t index, std::uint8_t first_sub, std::uint8_t last_sub) {
    for (unsigned sub = first_sub; sub <= last_sub; ++sub) device_stored_.insert({index, static_cast<std::uint8_t>(sub)});
  }
  /// Every value of the store file refused since power-on, as "file:line: reason" (also logged
  /// as a warning): it fails a check an SDO download would make (no such entry, read-only or
  /// constant, wrong length, outside the limits, a node-relative value that overflows).
  const std::vector<std::string>& rejected() const { return rejected_; }
  /// Injected failure of the non-volatile memory (fault injection): save/restore abort
  /// with 0x06060000.
  void set_failing(bool failing) { store_.set_failing(failing); }
  bool failing() const { return store_.failing(); }

 private:
  using Ranges = std::vector<std::pair<std::uint16_t, std::uint16_t>>;
  Ranges group_ranges(std::uint8_t sub) const;
  bool in_pending_restore(std::uint16_t index) const;
  static bool storable(const OdEntry& e);
  std::string refusal(const ParameterStore::Key& key, const ParameterStore::Value& v, Bytes& out) const;

  ObjectDictionary& od_;
  const StorePolicy& policy_;
  const NodeStatus& status_;
  const std::string& node_name_;
  SilenceRequest& silence_;
  ParameterStore store_;
  std::set<std::uint8_t> pending_restore_;
  std::set<ParameterStore::Key> device_stored_;
  std::set<ParameterStore::Key> reported_;
  std::vector<std::string> rejected_;
};

}  // namespace canopen
