// The HLT 1100's EMCY codes (§2.7 of the digest: the manual names 0000h and 8100h; 0xFF00, 5000h and 6300h are the digest's recommendations for the 6503h alarms).
// The frame decoder and the API print them by these words (devices::Device::emcy_codes()).
#pragma once

#include <span>

#include "devices/device.h"

namespace hlt1100 {

std::span<const devices::EmcyCode> emcy_codes();

}  // namespace hlt1100
