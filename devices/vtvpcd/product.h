// The VT-VPCD as a registry product: `vplant node --device vtvpcd`, `vplant eds vtvpcd`.
#pragma once

#include <string>

#include "devices/product.h"

namespace vtvpcd {

devices::Product product();
/// The EDS of the emulated card with its default configuration (what devices/vtvpcd/vtvpcd.eds holds; the card has no variants).
std::string eds(const std::string& variant = {});

}  // namespace vtvpcd
