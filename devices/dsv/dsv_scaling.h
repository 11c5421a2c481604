// The DSV manual's scaling of its process values and valve parameters (DSP 408 objects): the
// set-points and the actual value of the 16-bit modes in ±16384 = ±100 %, currents in steps of
// the output stage's full scale, ramps in ms.
#pragma once

#include <cstdint>

#include "devices/canopen/value_scaling.h"
#include "devices/dsv/dsv_options.h"

namespace dsv {

canopen::ValueScaling value_scaling(const DsvOptions& options, std::uint16_t index, std::uint8_t sub);

}  // namespace dsv
