// The MD2 manual's EMCY codes (§2.9 of its DSP 408 manual).
// The frame decoder and the API print them by these words (devices::Device::emcy_codes()).
#pragma once

#include <span>

#include "devices/device.h"

namespace md2 {

std::span<const devices::EmcyCode> emcy_codes();

}  // namespace md2
