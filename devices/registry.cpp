#include "devices/registry.h"

// Each product adds one include and one entry below.

namespace devices {

const std::vector<Product>& products() {
  static const std::vector<Product> kProducts = [] {
    std::vector<Product> list;
    return list;
  }();
  return kProducts;
}

const Product* find_product(const std::string& name) {
  for (const auto& p : products())
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace devices
