#include "devices/vtvpcd/product.h"

#include "devices/canopen/eds.h"
#include "devices/vtvpcd/vtvpcd_device.h"

namespace vtvpcd {

std::string eds(const std::string& /*variant*/) {
  // The card as shipped: the Bus Manager areas are commissioning data (BODAC, flash), so the
  // EDS's PDO mappings are empty. The emulator's default configuration loads the manual's
  // example areas, as a commissioned card would; a DS-301 mapping cannot describe the example's
  // 2-byte Discrete Outputs placed as 4 bytes without a length mismatch (A16).
  devices::DeviceOptions options;
  options.settings = {{"tpdo_area", ""}, {"rpdo_area", ""}};
  std::string error;
  auto device = VtvpcdDevice::create(options, error);
  canopen::EdsFileInfo info;
  info.file_name = "vtvpcd.eds";
  info.description = "VT-VPCD closed-loop control electronics for axial piston pumps A4VS.. (HS4) and A2V.. (EO4), "
                     "CANopen (RE 30028-02-Z/08.06), as emulated by vplant";
  info.vendor_name = "Bosch Rexroth AG";
  info.product_name = "VT-VPCD";
  info.order_code = "VT-VPCD";
  info.simple_boot_up_slave = true;
  info.lss_supported = false;
  info.dummy_usage = 0;  // the Bus Manager maps parameters only, no dummy entries
  info.comments = {
      "All values written over the bus are kept in RAM only (no 0x1010/0x1011).",
      "PDO mapping: set with BODAC's Bus Manager (factory: empty); vplant settings tpdo_area/rpdo_area.",
      "TPDOs are sent only on their event timer (0x1800+n sub 5) in Operational; SYNC is ignored.",
      "Manufacturer objects: raw = round(EU * scale) with the scales of the manual's chapter 4.",
  };
  return canopen::write_eds(device->node().od(), info);
}

devices::Product product() {
  devices::Product p;
  p.name = "vtvpcd";
  p.description = "Bosch Rexroth VT-VPCD axial-piston pump controller (HS4/EO4), factory node-ID 63";
  p.make = [](const devices::DeviceOptions& options, std::string& error) -> std::unique_ptr<devices::Device> {
    return VtvpcdDevice::create(options, error);
  };
  p.eds = [](const std::string& variant) { return eds(variant); };
  return p;
}

}  // namespace vtvpcd
