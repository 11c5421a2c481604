// The EDS and DCF of a node as it is configured, not as it leaves the factory: a master that sets
// up its PDOs from the file must see the mapping the node really has (e.g. the DSV in control
// mode 1 maps other objects than the factory default). Both are written from the dictionary of a
// built, powered-on device; [FileInfo] and [DeviceInfo] come from the product's factory EDS.
#pragma once

#include <string>

#include "devices/canopen/eds.h"
#include "devices/device.h"
#include "devices/registry.h"

namespace devices {

/// The EDS of `product` built with `options` (variant, settings, node-ID): every writable entry's
/// DefaultValue is the value the node holds after power-on. Node-relative entries keep
/// "$NODEID+…" unless options.node_id is given, then they are written for that node-ID. Empty
/// with `error` set for options the product rejects.
std::string configured_eds(const Product& product, const DeviceOptions& options, std::string& error);

/// The DCF of a built device (powered on, its configuration applied): ParameterValue= per entry
/// with its current value, [DeviceComissioning] with its node-ID. `info` is the file's
/// [FileInfo]/[DeviceInfo] (e.g. from the product's factory EDS).
std::string device_dcf(Device& device, const canopen::EdsFileInfo& info, const canopen::DcfCommissioning& commissioning);

/// [FileInfo]/[DeviceInfo] of `product`'s factory EDS for `variant`.
canopen::EdsFileInfo factory_info(const Product& product, const std::string& variant);

}  // namespace devices
