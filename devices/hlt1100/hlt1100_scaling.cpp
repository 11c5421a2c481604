#include "devices/hlt1100/hlt1100_scaling.h"

namespace hlt1100 {

canopen::ValueScaling value_scaling(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub) {
  if (sub != 1) return {};
  switch (index) {
    case 0x6010:  // preset value
    case 0x6020:  // position value
      return canopen::scaled("mm", od.get<std::uint32_t>(0x6005, 1) * 1e-6);
    case 0x6030:  // speed value
      return canopen::scaled("mm/s", od.get<std::uint32_t>(0x6005, 2) * 0.01);
    default: return {};
  }
}

}  // namespace hlt1100
