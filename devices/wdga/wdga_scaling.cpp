#include "devices/wdga/wdga_scaling.h"

#include "devices/wdga/wdga_object_dictionary.h"

namespace wdga {

canopen::ValueScaling value_scaling(bool multiturn, const canopen::ObjectDictionary& od, std::uint16_t index,
                                    std::uint8_t sub) {
  const bool position = index == obj::kPosition || index == obj::kPreset || index == obj::kPositionHigh ||
                        index == obj::kPresetHigh;
  if (sub != 0 || !position) return {};
  constexpr std::uint32_t kPhysical = kPhysicalResolution;  // 6501h
  const bool scaling_on = od.get<std::uint16_t>(obj::kOperatingParameters) & 0x0004;
  std::uint32_t steps = scaling_on ? od.get<std::uint32_t>(obj::kUnitsPerRevolution) : kPhysical;
  if (steps == 0) steps = kPhysical;
  return multiturn ? canopen::scaled("turns", 1.0 / steps) : canopen::scaled("°", 360.0 / steps);
}

}  // namespace wdga
