// The HLT 1100 manual's scaling of its position and speed values: the measuring step of 6005h:01
// (nm; 100000 = 0.1 mm) and the speed step of 6005h:02 (0.01 mm/s; 10 = 0.1 mm/s).
#pragma once

#include <cstdint>

#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/value_scaling.h"

namespace hlt1100 {

canopen::ValueScaling value_scaling(const canopen::ObjectDictionary& od, std::uint16_t index, std::uint8_t sub);

}  // namespace hlt1100
