// A generic node built from any EDS file: the CiA 301 stack with the EDS's object dictionary and
// no product behaviour. Two operator-side conditions make every abort code reachable for master
// testing: "local_control" (the device is operated locally: application writes are refused with
// 0x08000021) and "internal_fault" (a general device fault: application accesses abort with
// 0x08000000).
#pragma once

#include <memory>
#include <string>

#include "devices/device.h"

namespace devices {

class EdsNode final : public Device {
 public:
  /// Loads `eds_path`; returns nullptr with a "file:line: reason" error on failure.
  static std::unique_ptr<EdsNode> load(const std::string& eds_path, const DeviceOptions& options, std::string& error);

  canopen::Node& node() override { return *node_; }
  sim::PortList ports() override { return {}; }
  std::vector<FaultInfo> faults() const override;
  std::string inject_fault(std::string_view name, bool active) override;

 private:
  explicit EdsNode(std::unique_ptr<canopen::Node> node);
  void install_operator_checks();

  std::unique_ptr<canopen::Node> node_;
  bool local_control_ = false;
  bool internal_fault_ = false;
};

}  // namespace devices
