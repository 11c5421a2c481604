// The EDS generated from the emulated dictionary: committed as devices/vtvpcd/vtvpcd.eds, byte-
// identical to what `vplant eds vtvpcd` prints, clean for the CiA 306 checker, and loading back
// into the same dictionary.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "devices/canopen/eds.h"
#include "devices/registry.h"
#include "devices/vtvpcd/manufacturer_objects.h"
#include "devices/vtvpcd/product.h"
#include "devices/vtvpcd/vtvpcd_device.h"

namespace {
std::string committed() {
  std::ifstream in(VTVPCD_EDS_PATH, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(VtvpcdEds, CommittedFileEqualsTheGeneratedOne) {
  const std::string text = vtvpcd::eds();
  EXPECT_EQ(committed(), text) << "regenerate with: vplant eds vtvpcd -o devices/vtvpcd/vtvpcd.eds";
  EXPECT_EQ(vtvpcd::product().eds(""), text);
}

TEST(VtvpcdEds, LoadsWithoutErrorsOrWarnings) {
  const std::string text = committed();
  const auto problems = canopen::check_eds(text, "vtvpcd.eds");
  for (const auto& p : problems) ADD_FAILURE() << p.to_string();
  canopen::EdsError error;
  std::vector<canopen::EdsError> warnings;
  auto od = canopen::parse_eds(text, "vtvpcd.eds", error, nullptr, &warnings);
  ASSERT_TRUE(od) << error.to_string();
  EXPECT_TRUE(warnings.empty());

  std::string why;
  devices::DeviceOptions factory;
  factory.settings = {{"tpdo_area", ""}, {"rpdo_area", ""}};
  auto device = vtvpcd::VtvpcdDevice::create(factory, why);
  const auto& emulated = device->node().od();
  ASSERT_EQ(od->objects().size(), emulated.objects().size());
  for (const auto& [index, object] : emulated.objects()) {
    const auto* loaded = od->object(index);
    ASSERT_NE(loaded, nullptr) << std::hex << index;
    ASSERT_EQ(loaded->entries.size(), object.entries.size()) << std::hex << index;
    for (const auto& [sub, e] : object.entries) {
      const auto* l = od->entry(index, sub);
      ASSERT_NE(l, nullptr);
      EXPECT_EQ(l->type, e.type) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(l->access, e.access) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(l->pdo_mappable, e.pdo_mappable) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(l->default_for_node(63), e.default_for_node(63)) << std::hex << index << ":" << int(sub);
      EXPECT_EQ(l->name, e.name);
    }
  }
  // All 116 manufacturer objects, no store/restore.
  for (const auto& spec : vtvpcd::manufacturer_objects()) EXPECT_NE(od->object(spec.index), nullptr);
  EXPECT_EQ(od->object(0x1010), nullptr);
  EXPECT_EQ(od->object(0x1011), nullptr);
  EXPECT_EQ(od->entry(0x1A00, 0)->as<int>(), 0);  // factory: no Bus Manager mapping
}

TEST(VtvpcdEds, RegisteredAsAProduct) {
  const auto* p = devices::find_product("vtvpcd");
  ASSERT_NE(p, nullptr);
  std::string error;
  devices::DeviceOptions o;
  o.node_id = 12;
  auto d = p->make(o, error);
  ASSERT_TRUE(d) << error;
  EXPECT_EQ(d->node().node_id(), 12);
  o.settings["bogus"] = "1";
  EXPECT_FALSE(p->make(o, error));
  EXPECT_NE(error.find("bogus"), std::string::npos);
  o.settings.clear();
  o.variant = "X";
  EXPECT_FALSE(p->make(o, error));
}
