// Device node address (0x2000) and bit rate (0x2001), settable over CAN; a written value takes
// effect at the next communication reset or power cycle, and survives power-off only if saved
// (it belongs to the application group). Reset Node reloads the stored value first, so it
// discards an unsaved change.
#pragma once

#include <cstdint>

#include "devices/canopen/node.h"

namespace wandfluh {

class NodeAddress {
 public:
  static constexpr std::uint16_t kNodeAddress = 0x2000;
  static constexpr std::uint16_t kBitRate = 0x2001;

  /// Adds the two objects (defaults: node 1, 20 kbit/s) to `od`.
  static void add_objects(canopen::ObjectDictionary& od);

  explicit NodeAddress(canopen::Node& node);
  /// Communication reset: the node-ID and bit rate in the dictionary become the active ones.
  void apply();
  std::uint16_t active_bit_rate_kbit() const { return bit_rate_; }

 private:
  canopen::Node& node_;
  std::uint16_t bit_rate_ = 20;
};

}  // namespace wandfluh
