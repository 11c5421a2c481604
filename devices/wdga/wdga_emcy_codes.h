// The WDGA manual's EMCY codes (Tab. 7.7).
// The frame decoder and the API print them by these words (devices::Device::emcy_codes()).
#pragma once

#include <span>

#include "devices/device.h"

namespace wdga {

std::span<const devices::EmcyCode> emcy_codes();

}  // namespace wdga
