// The HLT 1100 as a registry product: `vplant node --device hlt1100`, `vplant eds hlt1100`.
#pragma once

#include <string>

#include "devices/product.h"

namespace hlt1100 {

devices::Product product();
/// The EDS with default settings (no variants: `variant` is ignored).
std::string eds(const std::string& variant = {});

}  // namespace hlt1100
