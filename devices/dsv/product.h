// The DSV's entry in the product registry and its EDS (WAGDSVC1.eds, §6.3).
#pragma once

#include <string>

#include "devices/product.h"

namespace dsv {

devices::Product product();
/// The EDS generated from the emulated object dictionary of `variant` ("" = amplifier).
std::string eds(const std::string& variant = {});

}  // namespace dsv
