// The VT-VPCD manual's EMCY codes (§3.5).
// The frame decoder and the API print them by these words (devices::Device::emcy_codes()).
#pragma once

#include <span>

#include "devices/device.h"

namespace vtvpcd {

std::span<const devices::EmcyCode> emcy_codes();

}  // namespace vtvpcd
