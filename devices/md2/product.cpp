#include "devices/md2/product.h"

#include "devices/canopen/eds.h"
#include "devices/md2/md2_device.h"
#include "devices/md2/md2_object_dictionary.h"

namespace md2 {

std::string eds(const std::string& variant) {
  devices::DeviceOptions options;
  options.variant = variant;
  Md2Options o;
  (void)o.read(options);
  canopen::EdsFileInfo info;
  info.file_name = "WAGMD2C1.eds";
  info.description = o.variant == Variant::Controller ? "MD2 controller, CANopen DSP 408" : "MD2 amplifier, CANopen DSP 408";
  info.vendor_name = "Wandfluh AG";
  info.vendor_number = wandfluh::kVendorId;
  info.product_name = o.variant == Variant::Controller ? "MD2 controller" : "MD2 amplifier";
  info.baud_rates_kbit = {10, 20, 50, 100, 125, 250, 500, 1000};
  info.simple_boot_up_slave = true;
  info.lss_supported = false;
  return canopen::write_eds(build_object_dictionary(o), info);
}

devices::Product product() {
  return devices::Product{
      "md2",
      "Wandfluh MD2 valve electronics, CANopen CiA DSP 408 (up to 8 channels)",
      {"amplifier", "controller"},
      [](const devices::DeviceOptions& options, std::string& error) -> std::unique_ptr<devices::Device> {
        return Md2Device::create(options, error);
      },
      [](const std::string& variant) { return eds(variant); },
  };
}

}  // namespace md2
