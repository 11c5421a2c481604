#include "devices/profiles/wandfluh/node_address.h"

namespace wandfluh {

using canopen::Access;
using canopen::DataType;
using canopen::ObjectDictionary;
using canopen::SdoAbort;

void NodeAddress::add_objects(ObjectDictionary& od) {
  auto& id = od.add_var(kNodeAddress, "Device node address", DataType::Unsigned8, Access::ReadWrite, 1);
  id.low_limit = ObjectDictionary::encode(DataType::Unsigned8, 1);
  id.high_limit = ObjectDictionary::encode(DataType::Unsigned8, 127);
  od.add_var(kBitRate, "Device node baudrate", DataType::Unsigned16, Access::ReadWrite, 20);
  // §2.3 lists 10..1000 kbit/s without 100, 0x2001 lists 100 too: both are accepted.
  od.on_write<std::uint16_t>(kBitRate, 0, [](std::uint16_t kbit, canopen::Origin) {
    switch (kbit) {
      case 10: case 20: case 50: case 100: case 125: case 250: case 500: case 1000: return SdoAbort::None;
      default: return SdoAbort::ParameterIncompatible;
    }
  });
}

NodeAddress::NodeAddress(canopen::Node& node) : node_(node) {}

void NodeAddress::apply() {
  node_.set_pending_node_id(node_.od().get<std::uint8_t>(kNodeAddress));
  bit_rate_ = node_.od().get<std::uint16_t>(kBitRate);
}

}  // namespace wandfluh
