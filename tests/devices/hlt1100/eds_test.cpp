// The committed EDS equals the one generated from the emulated dictionary, and it reads back
// through the CiA 306 parser without a warning into the same dictionary.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "devices/canopen/eds.h"
#include "devices/hlt1100/hlt1100_device.h"
#include "devices/hlt1100/product.h"
#include "devices/registry.h"
#include "devices/hlt1100/hlt1100_object_dictionary.h"
#include "tests/support/canopen_harness.h"
#include "tests/support/read_file.h"

namespace hlt1100::test {
namespace {

using vtest::read_file;

TEST(Hlt1100Eds, CommittedFileIsTheGeneratedOne) {
  const std::string committed = read_file(std::string(VPLANT_SOURCE_DIR) + "/devices/hlt1100/hlt1100.eds");
  ASSERT_FALSE(committed.empty());
  EXPECT_EQ(committed, eds()) << "regenerate with: vplant eds hlt1100 > devices/hlt1100/hlt1100.eds";
}

TEST(Hlt1100Eds, ParsesWithoutWarningsIntoTheSameDictionary) {
  const std::string text = eds();
  EXPECT_TRUE(canopen::check_eds(text, "hlt1100.eds").empty());
  canopen::EdsError error;
  std::vector<canopen::EdsError> warnings;
  canopen::EdsFileInfo info;
  const auto parsed = canopen::parse_eds(text, "hlt1100.eds", error, &info, &warnings);
  ASSERT_TRUE(parsed) << error.to_string();
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(info.lss_supported);
  const auto original = make_object_dictionary(Settings{});
  ASSERT_EQ(parsed->objects().size(), original.objects().size());
  for (const auto& [index, object] : original.objects()) {
    for (const auto& [sub, e] : object.entries) {
      const auto* p = parsed->entry(index, sub);
      ASSERT_TRUE(p) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(p->type, e.type) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(p->access, e.access) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(p->pdo_mappable, e.pdo_mappable) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(p->default_value, e.default_value) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(p->node_id_relative, e.node_id_relative) << std::hex << index << ":" << int(sub);
    }
  }
}

TEST(Hlt1100Eds, RegistryEntry) {
  const auto* p = devices::find_product("hlt1100");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->eds(""), eds());
  std::string error;
  EXPECT_FALSE(p->make(devices::DeviceOptions{.node_id = 0, .variant = "x", .settings = {}, .store_path = ""}, error));
  EXPECT_FALSE(p->make(devices::DeviceOptions{.node_id = 0, .variant = "", .settings = {{"nope", "1"}}, .store_path = ""}, error));
  EXPECT_NE(error.find("unknown setting 'nope'"), std::string::npos);
  auto d = p->make(devices::DeviceOptions{}, error);
  ASSERT_TRUE(d) << error;
  EXPECT_EQ(d->node().node_id(), 1);
  EXPECT_EQ(d->set_input("position", 0.1), "");
  // The value lands on the port the sensor measures: 100.0 mm = 1000 steps of 0.1 mm in 6020h:01.
  const auto ports = d->ports();
  const auto port = std::find_if(ports.begin(), ports.end(), [](const auto& port_info) { return port_info.name == "position"; });
  ASSERT_NE(port, ports.end());
  EXPECT_DOUBLE_EQ(*port->value, 0.1);
  vtest::CanopenHarness h(d->node());
  h.power_on();
  h.run_ms(2);
  EXPECT_EQ(h.read_u(0x6020, 1), 1000u);
  EXPECT_NE(d->set_input("nope", 0.1).find("unknown input 'nope'"), std::string::npos);
  EXPECT_NE(d->inject_fault("nope", true), "");
}

}  // namespace
}  // namespace hlt1100::test
