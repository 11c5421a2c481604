#include "devices/configured_eds.h"

#include "devices/canopen/node.h"

namespace devices {

namespace {

// What a master reads to learn the configuration: the communication area (PDO parameters and
// mappings, read-only ones included, e.g. the DSV's mode-dependent mapping) and every writable
// entry; not write-only entries or DOMAINs.
bool is_configuration(const canopen::OdEntry& e, std::uint16_t index) {
  if (e.access == canopen::Access::WriteOnly || e.type == canopen::DataType::Domain) return false;
  return index < 0x2000 || e.writable();
}

// Refreshes every readable entry as an SDO upload would see it (read hooks run).
void read_all(canopen::ObjectDictionary& od) {
  for (const auto& [index, object] : od.objects()) {
    for (const auto& [sub, entry] : object.entries) {
      canopen::OdEntry& e = *od.entry(index, sub);
      if (e.access != canopen::Access::WriteOnly) (void)od.read(e, canopen::Origin::Sdo);
    }
  }
}

std::uint64_t node_relative_value(const canopen::OdEntry& e, std::uint8_t node_id) {
  return canopen::decode_unsigned(e.default_value) + node_id;
}

}  // namespace

canopen::EdsFileInfo factory_info(const Product& product, const std::string& variant) {
  canopen::EdsFileInfo info;
  canopen::EdsError error;
  (void)canopen::parse_eds(product.eds(variant), product.name + ".eds", error, &info);
  return info;
}

std::string configured_eds(const Product& product, const DeviceOptions& options, std::string& error) {
  auto device = product.make(options, error);
  if (!device) return {};
  device->power_on(sim::Time{});
  canopen::Node& node = device->node();
  const std::uint8_t id = node.node_id();
  auto& od = node.od();
  read_all(od);
  for (const auto& [index, object] : od.objects()) {
    for (const auto& [sub, entry] : object.entries) {
      canopen::OdEntry& e = *od.entry(index, sub);
      if (!is_configuration(e, index)) continue;
      if (e.node_id_relative && options.node_id == 0 &&
          canopen::decode_unsigned(e.value) == node_relative_value(e, id))
        continue;  // still "$NODEID+base": right for any node-ID the master gives it
      e.default_value = e.value.bytes();
      e.node_id_relative = false;
    }
  }
  canopen::EdsFileInfo info = factory_info(product, options.variant);
  std::string settings;
  for (const auto& [k, v] : options.settings) settings += (settings.empty() ? "" : ", ") + k + "=" + v;
  info.comments.push_back("Configured: variant " + (options.variant.empty() ? std::string("(default)") : options.variant) +
                          (settings.empty() ? "" : ", settings " + settings) +
                          (options.node_id != 0 ? ", node-ID " + std::to_string(options.node_id) : ""));
  return canopen::write_eds(node.od(), info);
}

std::string device_dcf(Device& device, const canopen::EdsFileInfo& info, const canopen::DcfCommissioning& commissioning) {
  read_all(device.node().od());
  return canopen::write_dcf(device.node().od(), info, commissioning);
}

}  // namespace devices
