// Which of the 16 binary parameter sets is in use (digest §4.2, §3.6; manual §4.51, §4.113):
// Trigger bits 0-15 select set n over the bus, Trigger bit 16 is slave mode, and with DI6
// "binary enable" the discrete inputs DI1..DI4 code the set (weights 1, 2, 4, 8). Bus selection
// wins over the inputs. Level-controlled: the selection holds while the bit/inputs stay.
#pragma once

#include <bit>
#include <cstdint>

#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

/// Discrete Inputs 0x2F27 bit masks (the manual counts bits from 1: "bit 1" = 0x0001).
namespace di {
inline constexpr std::uint16_t kBinary1 = 0x0001;  ///< DI1
inline constexpr std::uint16_t kBinary2 = 0x0002;  ///< DI2
inline constexpr std::uint16_t kBinary4 = 0x0004;  ///< DI3
inline constexpr std::uint16_t kBinary8 = 0x0008;  ///< DI4
inline constexpr std::uint16_t kMaster = 0x0010;   ///< DI5
inline constexpr std::uint16_t kBinaryEnable = 0x0020;  ///< DI6
inline constexpr std::uint16_t kEnable = 0x0100;   ///< Enable
}  // namespace di

inline constexpr std::uint32_t kTriggerSlave = 0x00010000u;

struct SetSelection {
  int set = 0;                  ///< k: the set in use, or (direct mode) the one DI1..DI4 code, for the readouts
  bool binary = false;          ///< a binary set supplies the commands
  bool by_bus = false;          ///< selected by Trigger bits 0-15
  bool slave = false;           ///< Trigger bit 16
  bool trigger_invalid = false; ///< several of bits 0-15 with trigger_multibit = fault (fault 18)
  int group() const { return set / 4; }  ///< Contr P/I group: sets 4g..4g+3
  bool operator==(const SetSelection&) const = default;
};

/// Inline: it runs in every control cycle.
inline SetSelection select_binary_set(std::uint32_t trigger, std::uint16_t discrete_inputs, MultiBitTrigger multibit) {
  SetSelection s;
  s.slave = (trigger & kTriggerSlave) != 0;
  const auto bus_bits = static_cast<std::uint16_t>(trigger & 0xFFFFu);
  const int coded = discrete_inputs & 0x000F;
  if (bus_bits != 0) {
    s.binary = true;
    s.by_bus = true;
    s.set = std::countr_zero(bus_bits);  // the lowest set bit
    s.trigger_invalid = multibit == MultiBitTrigger::Fault && std::popcount(bus_bits) > 1;
  } else if (discrete_inputs & di::kBinaryEnable) {
    s.binary = true;
    s.set = coded;
  } else {
    s.set = coded;  // direct mode: the readouts 0x2F2F/0x2F30/0x2F31 still follow DI1..DI4
  }
  return s;
}

}  // namespace vtvpcd
