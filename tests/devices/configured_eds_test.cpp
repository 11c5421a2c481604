// configured_eds(): the EDS of a product as its settings configure it. The reference plant's DSV
// (control mode 1) maps other objects than the factory file says; the configured EDS must say
// what the running node's dictionary holds.
#include "devices/configured_eds.h"

#include <gtest/gtest.h>

#include "devices/canopen/eds.h"
#include "devices/canopen/node.h"

namespace {

const std::map<std::string, std::string> kDsvMode1 = {{"device_local", "0"}, {"control_mode", "1"}, {"mode_of_operation", "2"}};

canopen::ObjectDictionary parse(const std::string& text) {
  canopen::EdsError error;
  std::vector<canopen::EdsError> warnings;
  auto od = canopen::parse_eds(text, "test.eds", error, nullptr, &warnings);
  EXPECT_TRUE(od) << error.to_string();
  EXPECT_TRUE(warnings.empty()) << warnings.front().to_string();
  return od ? std::move(*od) : canopen::ObjectDictionary{};
}

// Every PDO parameter and mapping entry of `node` as an SDO upload reads it, against `eds`.
void expect_pdo_entries_match(canopen::Node& node, const canopen::ObjectDictionary& eds) {
  int compared = 0;
  for (const auto& [index, object] : node.od().objects()) {
    if (index < 0x1400 || index > 0x1BFF) continue;
    for (const auto& [sub, entry] : object.entries) {
      std::vector<std::uint8_t> value;
      ASSERT_EQ(node.od().read(index, sub, value, canopen::Origin::Sdo), canopen::SdoAbort::None);
      const canopen::OdEntry* e = eds.entry(index, sub);
      ASSERT_NE(e, nullptr) << std::hex << index << ":" << int(sub);
      auto expected = e->default_value;
      if (e->node_id_relative) {
        expected = canopen::ObjectDictionary::encode(e->type, canopen::decode_unsigned(expected) + node.node_id());
      }
      EXPECT_EQ(expected, value) << std::hex << index << ":" << int(sub);
      ++compared;
    }
  }
  EXPECT_GT(compared, 10);
}

}  // namespace

TEST(ConfiguredEds, DsvInControlMode1HasTheRunningNodesMappingNotTheFactoryOne) {
  const devices::Product* dsv = devices::find_product("dsv");
  ASSERT_NE(dsv, nullptr);
  devices::DeviceOptions options;
  options.settings = kDsvMode1;
  std::string error;
  const std::string text = devices::configured_eds(*dsv, options, error);
  ASSERT_FALSE(text.empty()) << error;
  const auto configured = parse(text);
  const auto factory = parse(dsv->eds(""));

  // The mapping differs from the factory file somewhere in 1600h-17FFh / 1A00h-1BFFh.
  int differences = 0;
  for (const auto& [index, object] : configured.objects()) {
    if (!((index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF))) continue;
    for (const auto& [sub, e] : object.entries) {
      const canopen::OdEntry* f = factory.entry(index, sub);
      differences += f == nullptr || f->default_value != e.default_value;
    }
  }
  EXPECT_GT(differences, 0);

  // ... and matches the node a scenario builds with the same settings.
  auto node = dsv->make(options, error);
  ASSERT_NE(node, nullptr) << error;
  node->power_on(sim::Time{});
  expect_pdo_entries_match(node->node(), configured);
}

TEST(ConfiguredEds, NodeIdResolvesNodeRelativeValues) {
  const devices::Product* md2 = devices::find_product("md2");
  ASSERT_NE(md2, nullptr);
  devices::DeviceOptions options;
  options.node_id = 9;
  std::string error;
  const std::string text = devices::configured_eds(*md2, options, error);
  ASSERT_FALSE(text.empty()) << error;
  const auto od = parse(text);
  const canopen::OdEntry* tpdo1 = od.entry(0x1800, 1);
  ASSERT_NE(tpdo1, nullptr);
  EXPECT_FALSE(tpdo1->node_id_relative);
  EXPECT_EQ(canopen::decode_unsigned(tpdo1->default_value) & 0x7FF, 0x189u);
  EXPECT_EQ(text.find("$NODEID+0x180\n"), std::string::npos);
  EXPECT_NE(md2->eds("").find("$NODEID+0x180"), std::string::npos);  // the factory file keeps it relative
}

TEST(ConfiguredEds, BadSettingIsAnError) {
  const devices::Product* dsv = devices::find_product("dsv");
  ASSERT_NE(dsv, nullptr);
  devices::DeviceOptions options;
  options.settings = {{"no_such_knob", "1"}};
  std::string error;
  EXPECT_EQ(devices::configured_eds(*dsv, options, error), "");
  EXPECT_NE(error.find("no_such_knob"), std::string::npos) << error;
}
