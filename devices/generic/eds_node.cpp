#include "devices/generic/eds_node.h"

#include "devices/canopen/eds.h"
#include "devices/canopen/lss_slave.h"
#include "devices/settings_reader.h"
#include "sim/log.h"

namespace devices {

std::unique_ptr<EdsNode> EdsNode::load(const std::string& eds_path, const DeviceOptions& options, std::string& error) {
  canopen::EdsError eds_error;
  canopen::EdsFileInfo info;
  std::vector<canopen::EdsError> warnings;
  auto od = canopen::load_eds(eds_path, eds_error, &info, &warnings,
                              options.strict_eds ? canopen::EdsStrictness::Strict : canopen::EdsStrictness::Tolerant);
  if (!od) {
    error = eds_error.to_string();
    return nullptr;
  }
  // A non-conformant but usable file still runs; the operator sees what is wrong with it.
  for (const auto& w : warnings) sim::log(sim::LogLevel::Warn, "{}", w.to_string());
  if (!options.variant.empty()) {
    error = "an EDS node has no variants";
    return nullptr;
  }
  if (!options.settings.empty()) {
    error = unknown_setting(options.settings.begin()->first, {});  // an EDS node has no settings
    return nullptr;
  }
  canopen::NodePolicy policy;
  policy.store.path = options.store_path;
  // The error history is as deep as the file's 0x1003 (sub 0 must never count more entries
  // than the object has).
  const auto* history = od->object(0x1003);
  policy.emcy.history_depth = history && !history->entries.empty() ? history->entries.rbegin()->first : 0;
  const std::uint8_t id = options.node_id == 0 ? 1 : options.node_id;
  auto node = std::make_unique<canopen::Node>("eds", std::move(*od), std::move(policy), id);
  if (info.lss_supported) node->enable_lss(canopen::LssPolicy{});  // identity from 0x1018
  auto device = std::unique_ptr<EdsNode>(new EdsNode(std::move(node)));
  device->install_operator_checks();
  return device;
}

EdsNode::EdsNode(std::unique_ptr<canopen::Node> node) : node_(std::move(node)) {
  node_->set_transition_log(&transition_log_);
}

void EdsNode::install_operator_checks() {
  // Application area only: the communication area stays configurable by the master.
  auto& od = node_->od();
  for (const auto& [index, object] : od.objects()) {
    if (index < 0x2000) continue;
    for (const auto& [sub, entry] : object.entries) {
      od.add_check(
          index, sub,
          [this](const canopen::OdEntry&, std::span<std::uint8_t>, canopen::Origin origin) {
            if (origin != canopen::Origin::Sdo && origin != canopen::Origin::Pdo) return canopen::SdoAbort::None;
            if (internal_fault_) return canopen::SdoAbort::General;
            if (local_control_) return canopen::SdoAbort::DataLocalControl;
            return canopen::SdoAbort::None;
          },
          canopen::CheckStage::State);
      od.add_read_hook(index, sub, [this](canopen::OdEntry&, canopen::Origin origin) {
        return internal_fault_ && origin == canopen::Origin::Sdo ? canopen::SdoAbort::General : canopen::SdoAbort::None;
      });
    }
  }
}

std::vector<FaultInfo> EdsNode::faults() const {
  return {{"local_control", "device operated locally: application writes abort with 0x08000021"},
          {"internal_fault", "general device fault: application accesses abort with 0x08000000"}};
}

std::string EdsNode::inject_fault(std::string_view name, bool active) {
  if (name == "local_control") {
    local_control_ = active;
    return {};
  }
  if (name == "internal_fault") {
    internal_fault_ = active;
    return {};
  }
  return Device::inject_fault(name, active);
}

}  // namespace devices
