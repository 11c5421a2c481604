// The product registry: every emulated product by name, so `vplant node --device NAME`,
// `vplant eds NAME` and scenario files create devices without knowing their classes.
#pragma once

#include <string>
#include <vector>

#include "devices/product.h"

namespace devices {

const std::vector<Product>& products();
const Product* find_product(const std::string& name);

}  // namespace devices
