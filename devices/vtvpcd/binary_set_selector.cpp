#include "devices/vtvpcd/binary_set_selector.h"

#include <bit>

namespace vtvpcd {

SetSelection select_binary_set(std::uint32_t trigger, std::uint16_t discrete_inputs, MultiBitTrigger multibit) {
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
