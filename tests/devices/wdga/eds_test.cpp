// The committed EDS equals the one generated from the emulated dictionary, and it reads back
// through the CiA 306 parser without a warning into the same dictionary.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "devices/canopen/eds.h"
#include "devices/wdga/wdga_device.h"
#include "devices/wdga/product.h"
#include "devices/registry.h"
#include "devices/wdga/wdga_object_dictionary.h"
#include "tests/support/read_file.h"

namespace wdga::test {
namespace {

using vtest::read_file;

class WdgaEds : public ::testing::TestWithParam<std::string> {};

TEST_P(WdgaEds, CommittedFileIsTheGeneratedOne) {
  const std::string committed = read_file(std::string(VPLANT_SOURCE_DIR) + "/devices/wdga/wdga-" + GetParam() + ".eds");
  ASSERT_FALSE(committed.empty());
  EXPECT_EQ(committed, eds(GetParam())) << "regenerate with: vplant eds wdga --variant " << GetParam();
}

TEST_P(WdgaEds, ParsesWithoutWarningsIntoTheSameDictionary) {
  const std::string text = eds(GetParam());
  EXPECT_TRUE(canopen::check_eds(text, "wdga.eds").empty());
  canopen::EdsError error;
  std::vector<canopen::EdsError> warnings;
  canopen::EdsFileInfo info;
  const auto parsed = canopen::parse_eds(text, "wdga.eds", error, &info, &warnings);
  ASSERT_TRUE(parsed) << error.to_string();
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(info.lss_supported);
  Settings s;
  ASSERT_EQ(parse_settings(GetParam(), {}, s), "");
  const auto original = make_object_dictionary(s);
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

INSTANTIATE_TEST_SUITE_P(Variants, WdgaEds, ::testing::Values("multiturn", "singleturn"));

TEST(WdgaRegistry, EntryVariantsAndErrors) {
  const auto* p = devices::find_product("wdga");
  ASSERT_TRUE(p);
  EXPECT_EQ(p->variants, (std::vector<std::string>{"multiturn", "singleturn"}));
  EXPECT_EQ(p->eds(""), eds("multiturn"));
  std::string error;
  EXPECT_FALSE(p->make(devices::DeviceOptions{.node_id = 0, .variant = "x", .settings = {}, .store_path = ""}, error));
  EXPECT_FALSE(p->make(devices::DeviceOptions{.node_id = 0, .variant = "", .settings = {{"signal", "ramp:"}}, .store_path = ""}, error));
  auto d = p->make(devices::DeviceOptions{}, error);
  ASSERT_TRUE(d) << error;
  EXPECT_EQ(d->node().node_id(), 127);
  EXPECT_EQ(d->set_input("angle", 1.0), "");
  EXPECT_NE(d->inject_fault("nope", true), "");
}

}  // namespace
}  // namespace wdga::test
