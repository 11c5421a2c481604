// A product's faults as data: one row per fault with its name, the EMCY code it raises, what it
// does, and the action that switches it. Each product's faults() and inject_fault() read its
// table, so a fault is named once.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "devices/device.h"

namespace devices {

template <typename D>
struct FaultEntry {
  const char* name;
  std::uint16_t emcy;       ///< the EMCY code it raises; 0 = none (an SDO abort, a refusal, silence)
  const char* description;  ///< what it does, as `vplant devices` and the docs show it
  void (*apply)(D& device, bool active);
  bool (*available)(const D& device) = nullptr;  ///< nullptr = always (else e.g. only with solenoid B)
};

template <typename D>
std::vector<FaultInfo> fault_infos(std::span<const FaultEntry<D>> table, const D& device) {
  std::vector<FaultInfo> out;
  for (const auto& f : table)
    if (!f.available || f.available(device)) out.push_back({f.name, f.description, f.emcy});
  return out;
}

/// Switches fault `name` from `table`; false if the table has no such fault for this device.
template <typename D>
bool apply_fault(std::span<const FaultEntry<D>> table, D& device, std::string_view name, bool active) {
  for (const auto& f : table) {
    if (name != f.name || (f.available && !f.available(device))) continue;
    f.apply(device, active);
    return true;
  }
  return false;
}

}  // namespace devices
