// The product registry: every emulated product by name, so `vplant node --device NAME`,
// `vplant eds NAME` and scenario files create devices without knowing their classes.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "devices/device.h"

namespace devices {

struct Product {
  std::string name;         ///< command-line / scenario name, e.g. "md2"
  std::string description;  ///< one line for `vplant devices`
  std::vector<std::string> variants;  ///< first = default; empty = no variants
  /// Builds the device; returns nullptr and sets `error` on bad options.
  std::function<std::unique_ptr<Device>(const DeviceOptions&, std::string& error)> make;
  /// The product's EDS text (CiA 306), generated from its object dictionary.
  std::function<std::string(const std::string& variant)> eds;
};

const std::vector<Product>& products();
const Product* find_product(const std::string& name);

}  // namespace devices
