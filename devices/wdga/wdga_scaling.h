// The WDGA manual's scaling of its position values: steps of the measuring units per revolution
// (6001h while scaling is on, 6000h bit 2; else the physical 16384 of 6501h), read as turns on the
// multiturn encoder and as degrees on the singleturn one.
#pragma once

#include <cstdint>

#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/value_scaling.h"

namespace wdga {

canopen::ValueScaling value_scaling(bool multiturn, const canopen::ObjectDictionary& od, std::uint16_t index,
                                    std::uint8_t sub);

}  // namespace wdga
