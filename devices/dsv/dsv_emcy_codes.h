// The DSV manual's EMCY codes (§2.9 of the DSP 408 manual, in its words).
// The frame decoder and the API print them by these words (devices::Device::emcy_codes()).
#pragma once

#include <span>

#include "devices/device.h"

namespace dsv {

std::span<const devices::EmcyCode> emcy_codes();

}  // namespace dsv
