// CiA 406 operating status (6500h), alarms (6503h) and warnings (6505h) as three machines of
// named bits (machines "cia406.status", "cia406.alarms", "cia406.warnings"): each product names
// the bits its manual documents; StatusRecorder records every change of a named bit into the
// device's transition log (none → BIT when it sets, BIT → none when it clears).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "devices/canopen/node.h"
#include "devices/state_machine_diagram.h"

namespace cia406 {

/// The bits a product's manual names in each word.
struct StatusBitNames {
  std::span<const devices::DiagramBit> status, alarms, warnings;
};

/// The three machines' descriptions (static text: `names` must outlive them).
std::vector<devices::MachineDiagram> status_diagrams(const StatusBitNames& names);

/// The three machines with their states now ("OFF" while unpowered), for Device::machines().
void append_status_machines(const canopen::Node& node, const StatusBitNames& names, std::vector<devices::MachineView>& out);

class StatusRecorder {
 public:
  StatusRecorder(canopen::Node& node, const StatusBitNames& names) : node_(node), names_(names) {}
  /// Once per process(): compares the three words with the last look (a few loads while
  /// nothing changes) and records each named bit that changed. Allocates nothing.
  void check();

  enum class Word : std::uint8_t { Status = 0, Alarms = 1, Warnings = 2 };
  /// The product sets `bits` of `word` for a device fault and sends EMCY `emcy_code` (0: its
  /// manual documents none): the next check() records those bits' setting with that cause
  /// (device_fault, the code, the bit's name) instead of `internal`. Allocates nothing.
  void raised_by_fault(Word word, std::uint16_t bits, std::uint16_t emcy_code);

 private:
  canopen::Node& node_;
  StatusBitNames names_;
  std::uint16_t last_[3] = {0, 0, 0};
  const canopen::OdEntry* entries_[3] = {nullptr, nullptr, nullptr};  ///< found at the first check
  bool bound_ = false;
  std::uint16_t fault_bits_[3] = {0, 0, 0};                ///< bits noted by raised_by_fault
  std::array<std::array<std::uint16_t, 16>, 3> fault_code_{};  ///< their EMCY codes, per bit
};

}  // namespace cia406
