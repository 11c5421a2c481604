// The WDGA as a registry product: `vplant node --device wdga`, `vplant eds wdga`.
#pragma once

#include <string>

#include "devices/product.h"

namespace wdga {

devices::Product product();
/// The EDS of a variant ("multiturn", "singleturn"; "" = multiturn) with default settings.
std::string eds(const std::string& variant = {});

}  // namespace wdga
