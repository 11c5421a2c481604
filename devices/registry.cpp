#include "devices/registry.h"

// Each product folder has a product.{h,cpp} (devices/product.h); it adds one include and one
// entry below, in `vplant devices` order.
#include "devices/dsv/product.h"
#include "devices/md2/product.h"
#include "devices/vtvpcd/product.h"
#include "devices/hlt1100/product.h"
#include "devices/wdga/product.h"

namespace devices {

const std::vector<Product>& products() {
  static const std::vector<Product> kProducts = [] {
    std::vector<Product> list;
    list.push_back(md2::product());
    list.push_back(dsv::product());
    list.push_back(vtvpcd::product());
    list.push_back(hlt1100::product());
    list.push_back(wdga::product());
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
