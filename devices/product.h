// What a product is to the rest of vplant: a name, its variants, how to build its device and its
// EDS. A leaf header: each product's product.cpp returns one of these, and only the registry
// (registry.h) lists them.
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

}  // namespace devices
