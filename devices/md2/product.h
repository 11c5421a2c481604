// The MD2's entry in the product registry and its EDS (WAGMD2C1.eds, §5.7).
#pragma once

#include <string>

#include "devices/product.h"

namespace md2 {

devices::Product product();
/// The EDS generated from the emulated object dictionary of `variant` ("" = amplifier).
std::string eds(const std::string& variant = {});

}  // namespace md2
