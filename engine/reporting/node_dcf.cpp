#include "engine/reporting/node_dcf.h"

#include "devices/canopen/eds.h"
#include "devices/configured_eds.h"
#include "engine/loading/scenario_loader.h"
#include "engine/running/world.h"

namespace scenario {

std::string node_dcf(Scenario scenario, const Environment& env, const std::string& node_name) {
  for (auto& bus : scenario.buses) bus.iface.clear();  // the file is about the node, not the wire
  World world(scenario, env, BuildOptions{}, scenario.clock.seed);
  NodeInstance* node = world.find_node(node_name);
  if (!node) {
    std::string known;
    for (const auto& n : world.nodes()) known += (known.empty() ? "" : ", ") + n.spec->name;
    throw LoadError(SourceMark{scenario.file, 0, 0}, "no node '" + node_name + "' (nodes: " + known + ")");
  }
  const NodeSpec& spec = *node->spec;
  node->device->power_on(sim::Time{});

  canopen::EdsFileInfo info;
  if (spec.device == "eds") {
    canopen::EdsError error;
    (void)canopen::load_eds(spec.eds, error, &info);
  } else if (const devices::Product* product = env.find_product ? env.find_product(spec.device) : nullptr) {
    info = devices::factory_info(*product, spec.variant);
  }
  info.file_name = spec.name + ".dcf";
  info.comments.push_back("DCF of node '" + spec.name + "' of scenario " + scenario.file + " (written by vplant dcf)");

  const auto b = static_cast<std::size_t>(node->bus);
  canopen::DcfCommissioning c;
  c.node_id = node->node_id;
  c.node_name = spec.name;
  c.baudrate_kbit = b < scenario.buses.size() ? scenario.buses[b].bitrate / 1000 : 0;
  c.network_name = world.buses()[b]->name();
  return devices::device_dcf(*node->device, info, c);
}

}  // namespace scenario
