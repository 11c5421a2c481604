#include "devices/dsv/product.h"

#include "devices/canopen/eds.h"
#include "devices/dsv/dsv_device.h"
#include "devices/dsv/dsv_object_dictionary.h"

namespace dsv {

std::string eds(const std::string& variant) {
  devices::DeviceOptions options;
  options.variant = variant;
  DsvOptions o;
  (void)o.read(options);
  canopen::EdsFileInfo info;
  info.file_name = "WAGDSVC1.eds";
  info.description = o.variant == Variant::Controller ? "DSV controller, CANopen DSP 408" : "DSV amplifier, CANopen DSP 408";
  info.vendor_name = "Wandfluh AG";
  info.vendor_number = wandfluh::kVendorId;
  info.product_name = o.variant == Variant::Controller ? "DSV controller" : "DSV amplifier";
  info.baud_rates_kbit = {10, 20, 50, 100, 125, 250, 500, 1000};
  info.simple_boot_up_slave = true;
  info.lss_supported = false;
  info.dummy_usage = 0;  // the mapping is fixed: nothing can map a dummy
  return canopen::write_eds(build_object_dictionary(o), info);
}

devices::Product product() {
  return devices::Product{
      "dsv",
      "Wandfluh DSV valve electronics, CANopen CiA DSP 408 (one valve, 1 or 2 solenoids)",
      {"amplifier", "controller"},
      [](const devices::DeviceOptions& options, std::string& error) -> std::unique_ptr<devices::Device> {
        return DsvDevice::create(options, error);
      },
      [](const std::string& variant) { return eds(variant); },
  };
}

}  // namespace dsv
