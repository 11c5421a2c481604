// node_dcf(): the DCF of a scenario's node, with its settings, `parameters:` overrides and
// node-ID; it round-trips through the project's own EDS reader.
#include "engine/reporting/node_dcf.h"

#include <gtest/gtest.h>

#include "devices/canopen/eds.h"
#include "engine/loading/scenario_loader.h"
#include "engine/running/world.h"
#include "tests/engine/test_world.h"

namespace {

const std::string kScenario = R"(
name: dcf
buses:
  - {name: field, bitrate: 250000}
nodes:
  - name: dsv
    device: dsv
    node_id: 2
    settings: {device_local: "0", control_mode: "1", mode_of_operation: "2"}
    parameters: {"0x1017": 100}
  - {name: md2, device: md2, node_id: 3}
clock: {duration: 1s}
)";

}  // namespace

TEST(NodeDcf, RoundTripsWithTheConfiguredValuesAndNodeId) {
  const auto s = scenario::parse_scenario(kScenario, "dcf.yaml", ".");
  const std::string text = scenario::node_dcf(s, scenario::default_environment(), "dsv");
  EXPECT_NE(text.find("[DeviceComissioning]\nNodeID=0x02\nNodeName=dsv\nBaudrate=250\nNetNumber=0\nNetworkName=field\n"),
            std::string::npos)
      << text.substr(0, 1500);

  canopen::EdsError error;
  std::vector<canopen::EdsError> warnings;
  const auto od = canopen::parse_eds(text, "dsv.dcf", error, nullptr, &warnings);
  ASSERT_TRUE(od) << error.to_string();
  EXPECT_TRUE(warnings.empty()) << warnings.front().to_string();

  // The running node of the same scenario: every value the DCF states is the node's value.
  scenario::World world(s, scenario::default_environment(), {}, 1);
  auto& node = world.find_node("dsv")->device->node();
  node.power_on(sim::Time{});
  int compared = 0;
  for (const auto& [index, object] : node.od().objects()) {
    for (const auto& [sub, entry] : object.entries) {
      if (entry.access == canopen::Access::WriteOnly || entry.type == canopen::DataType::Domain) continue;
      std::vector<std::uint8_t> value;
      if (node.od().read(index, sub, value, canopen::Origin::Sdo) != canopen::SdoAbort::None) continue;
      if (index >= 0x2000 && !entry.writable()) continue;  // measurements move; configuration does not
      const canopen::OdEntry* e = od->entry(index, sub);
      ASSERT_NE(e, nullptr) << std::hex << index << ":" << int(sub);
      EXPECT_FALSE(e->node_id_relative);
      EXPECT_EQ(e->default_value, value) << std::hex << index << ":" << int(sub);
      ++compared;
    }
  }
  EXPECT_GT(compared, 50);
  // The scenario's override (1017h = 100 ms) and the node-ID's COB-IDs are in the file.
  EXPECT_EQ(canopen::decode_unsigned(od->entry(0x1017, 0)->default_value), 100u);
  EXPECT_EQ(canopen::decode_unsigned(od->entry(0x1800, 1)->default_value) & 0x7FF, 0x182u);
}

TEST(NodeDcf, UnknownNodeIsALoadError) {
  const auto s = scenario::parse_scenario(kScenario, "dcf.yaml", ".");
  try {
    (void)scenario::node_dcf(s, scenario::default_environment(), "valve");
    FAIL() << "no error";
  } catch (const scenario::LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("no node 'valve' (nodes: dsv, md2)"), std::string::npos) << e.what();
  }
}
