// docs/masters.md's summary table is true of the emulation: each product's factory node-ID, its
// heartbeat producer (1017h, 0 after power-on) and its heartbeat consumer (1016h).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "devices/canopen/node.h"
#include "devices/registry.h"

namespace {

std::string row_of(const std::string& doc, const std::string& label) {
  const auto at = doc.find("\n| " + label + " |");
  if (at == std::string::npos) return {};
  return doc.substr(at + 1, doc.find('\n', at + 1) - at - 1);
}

std::string cell(const std::string& row, int n) {  // 0 = the label
  std::size_t at = 0;
  for (int i = 0; i <= n; ++i) at = row.find('|', at) + 1;
  const auto end = row.find('|', at);
  std::string c = row.substr(at, end - at);
  c.erase(0, c.find_first_not_of(' '));
  c.erase(c.find_last_not_of(' ') + 1);
  return c;
}

std::string masters_doc() {
  std::ifstream file(std::string(VPLANT_SOURCE_DIR) + "/docs/masters.md");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

TEST(MastersDocs, SummaryTableMatchesTheProducts) {
  const std::string doc = masters_doc();
  ASSERT_FALSE(doc.empty()) << "docs/masters.md missing";
  for (const auto& [label, name] : {std::pair{"MD2", "md2"}, std::pair{"DSV", "dsv"}, std::pair{"VT-VPCD", "vtvpcd"},
                                    std::pair{"HLT 1100", "hlt1100"}, std::pair{"WDGA", "wdga"}}) {
    const std::string row = row_of(doc, label);
    ASSERT_FALSE(row.empty()) << label;
    const devices::Product* product = devices::find_product(name);
    ASSERT_NE(product, nullptr) << name;
    std::string error;
    auto device = product->make(devices::DeviceOptions{}, error);
    ASSERT_NE(device, nullptr) << error;
    device->power_on(sim::Time{});
    auto& node = device->node();
    const int documented_id = std::stoi(cell(row, 1));
    const int id = node.node_id() != 0 && node.node_id() != canopen::Node::kUnconfigured ? node.node_id() : node.pending_node_id();
    EXPECT_EQ(id, documented_id) << label;

    const canopen::OdEntry* producer = node.od().entry(0x1017, 0);
    if (cell(row, 2) == "no") {
      EXPECT_EQ(producer, nullptr) << label;
    } else {
      EXPECT_EQ(cell(row, 2), "yes, 0") << label;
      ASSERT_NE(producer, nullptr) << label;
      EXPECT_EQ(canopen::decode_unsigned(producer->value), 0u) << label;
    }
    const canopen::OdEntry* consumers = node.od().entry(0x1016, 0);
    if (cell(row, 3) == "no") {
      EXPECT_TRUE(consumers == nullptr || canopen::decode_unsigned(consumers->value) == 0) << label;
    } else {
      EXPECT_EQ(cell(row, 3), "1016h:01") << label;
      ASSERT_NE(consumers, nullptr) << label;
      EXPECT_EQ(canopen::decode_unsigned(consumers->value), 1u) << label;
    }
  }
}

namespace {

std::uint32_t hex_cell(const std::string& c) { return static_cast<std::uint32_t>(std::stoul(c.substr(0, c.size() - 1), nullptr, 16)); }

}  // namespace

TEST(MastersDocs, IdentityTableMatchesTheProducts) {
  // 1000h and 1018h as the "Identity objects" table gives them ("absent" = the sub-index does not
  // exist), and the abort of an SDO write to 1000h that the text under it names.
  const std::string doc = masters_doc();
  ASSERT_FALSE(doc.empty()) << "docs/masters.md missing";
  for (const char* name : {"md2", "dsv", "vtvpcd", "hlt1100", "wdga"}) {
    SCOPED_TRACE(name);
    const std::string row = row_of(doc, std::string("`") + name + "`");
    ASSERT_FALSE(row.empty());
    std::string error;
    auto device = devices::find_product(name)->make(devices::DeviceOptions{}, error);
    ASSERT_NE(device, nullptr) << error;
    device->power_on(sim::Time{});
    auto& od = device->node().od();
    ASSERT_NE(od.entry(0x1000, 0), nullptr);
    EXPECT_EQ(canopen::decode_unsigned(od.entry(0x1000, 0)->value), hex_cell(cell(row, 1)));
    EXPECT_EQ(canopen::decode_unsigned(od.entry(0x1018, 0)->value), std::stoul(cell(row, 2)));
    for (int sub = 1; sub <= 4; ++sub) {
      const std::string c = cell(row, 2 + sub);
      const canopen::OdEntry* e = od.entry(0x1018, static_cast<std::uint8_t>(sub));
      if (c == "absent") {
        EXPECT_EQ(e, nullptr) << "1018h:" << sub;
      } else {
        ASSERT_NE(e, nullptr) << "1018h:" << sub;
        EXPECT_EQ(canopen::decode_unsigned(e->value), hex_cell(c)) << "1018h:" << sub;
      }
    }
    const std::uint8_t zero[4] = {0, 0, 0, 0};
    const auto abort = od.write(0x1000, 0, zero, canopen::Origin::Sdo);
    EXPECT_EQ(canopen::code(abort), std::string(name) == "wdga" ? 0x06010002u : 0x06010000u);
  }
}
