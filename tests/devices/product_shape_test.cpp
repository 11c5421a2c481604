// Every product has the same shape: registered by its folder's product.cpp, built as its
// <Product>Device, its settings read by the one strict reader (one unknown-setting error), and
// its faults a table whose entries inject and raise the EMCY code they name.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "devices/canopen/frame_decoder.h"
#include "devices/dsv/dsv_device.h"
#include "devices/hlt1100/hlt1100_device.h"
#include "devices/md2/md2_device.h"
#include "devices/registry.h"
#include "devices/vtvpcd/vtvpcd_device.h"
#include "devices/wdga/wdga_device.h"
#include "tests/support/canopen_harness.h"

namespace {

std::unique_ptr<devices::Device> make(const devices::Product& p, std::map<std::string, std::string> settings = {}) {
  devices::DeviceOptions o;
  o.settings = std::move(settings);
  std::string error;
  auto d = p.make(o, error);
  EXPECT_TRUE(d) << p.name << ": " << error;
  return d;
}

TEST(ProductShape, EveryProductRegistersThroughItsFolderAsItsDeviceClass) {
  std::vector<std::string> names;
  for (const auto& p : devices::products()) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"md2", "dsv", "vtvpcd", "hlt1100", "wdga"}));
  for (const auto& p : devices::products()) {
    const std::filesystem::path dir = std::filesystem::path(VPLANT_SOURCE_DIR) / "devices" / p.name;
    for (const auto& file : {"product.h", "product.cpp", "CMakeLists.txt"})
      EXPECT_TRUE(std::filesystem::exists(dir / file)) << (dir / file);
    for (const auto& file : {p.name + "_device.h", p.name + "_device.cpp"})
      EXPECT_TRUE(std::filesystem::exists(dir / file)) << (dir / file);
    EXPECT_FALSE(p.description.empty()) << p.name;
    ASSERT_TRUE(p.make && p.eds) << p.name;
    EXPECT_NE(p.eds("").find("[DeviceInfo]"), std::string::npos) << p.name;
  }
  EXPECT_TRUE(dynamic_cast<md2::Md2Device*>(make(*devices::find_product("md2")).get()));
  EXPECT_TRUE(dynamic_cast<dsv::DsvDevice*>(make(*devices::find_product("dsv")).get()));
  EXPECT_TRUE(dynamic_cast<vtvpcd::VtvpcdDevice*>(make(*devices::find_product("vtvpcd")).get()));
  EXPECT_TRUE(dynamic_cast<hlt1100::Hlt1100Device*>(make(*devices::find_product("hlt1100")).get()));
  EXPECT_TRUE(dynamic_cast<wdga::WdgaDevice*>(make(*devices::find_product("wdga")).get()));
}

TEST(ProductShape, AnUnknownSettingIsOneErrorListingTheKnownNames) {
  const std::map<std::string, std::string> known = {
      {"md2", "dither_frequency"}, {"dsv", "dither_frequency"}, {"vtvpcd", "pump_type"},
      {"hlt1100", "boot_delay_ms"}, {"wdga", "position_error_emcy"}};
  for (const auto& p : devices::products()) {
    devices::DeviceOptions o;
    o.settings = {{"no_such_knob", "1"}};
    std::string error;
    EXPECT_FALSE(p.make(o, error)) << p.name;
    EXPECT_EQ(error.rfind("unknown setting 'no_such_knob' (known: ", 0), 0u) << p.name << ": " << error;
    ASSERT_TRUE(known.count(p.name)) << p.name;
    EXPECT_NE(error.find(known.at(p.name)), std::string::npos) << p.name << ": " << error;
  }
}

// The EMCY codes a device sent, in order.
std::vector<std::uint16_t> emcy_codes_sent(const vtest::Frames& frames, std::uint8_t node_id) {
  std::vector<std::uint16_t> out;
  for (const auto& f : frames)
    if (f.id == 0x80u + node_id && f.data.size() == 8) out.push_back(static_cast<std::uint16_t>(f.data[0] | f.data[1] << 8));
  return out;
}

TEST(ProductShape, EveryFaultInjectsAndRaisesTheEmcyCodeItNames) {
  // Faults whose EMCY needs more than the device at its defaults in Operational: a driven
  // solenoid (the DSV), the analog input or 4..20 mA in use, a store or a start-up (EEPROM), a
  // temperature sample (every 60 s), bus-off recovery; their own tests cover them.
  const std::set<std::string> conditional = {
      "dsv.solenoid_a_open", "dsv.solenoid_b_open", "dsv.actual_cable_break", "dsv.memory_failure",
      "md2.analog_signal_lost", "hlt1100.eeprom_error",
      "wdga.eeprom_error", "wdga.bus_off", "wdga.temperature_sensor_failure", "wdga.over_temperature"};
  std::set<std::string> not_raised;
  for (const auto& p : devices::products()) {
    for (const auto& info : make(p)->faults()) {
      auto device = make(p);
      vtest::CanopenHarness h(device->node());
      h.power_on();
      h.send(0x000, {0x01, 0x00});  // NMT start, all nodes
      h.run_ms(100);
      const std::uint8_t id = device->node().node_id();
      h.take();
      ASSERT_EQ(device->inject_fault(info.name, true), "") << p.name << "." << info.name;
      if (info.emcy == 0) continue;
      char hex[8];
      std::snprintf(hex, sizeof hex, "%04X", info.emcy);
      const std::string text = info.description;
      EXPECT_TRUE(text.find(hex) != std::string::npos || text.find("EMCY") != std::string::npos)
          << p.name << "." << info.name << ": " << text;
      bool in_table = false;
      for (const auto& c : device->emcy_codes()) in_table |= c.code == info.emcy;
      // The product's own code, or one CiA 301 defines (the decoder names both).
      EXPECT_TRUE(in_table || !canopen::emcy_code_text(info.emcy).empty()) << p.name << "." << info.name << " " << hex;
      h.run_ms(1500);
      const auto sent = emcy_codes_sent(h.take(), id);
      bool raised = false;
      for (auto c : sent) raised |= c == info.emcy;
      if (!raised) not_raised.insert(p.name + "." + info.name);
    }
  }
  EXPECT_EQ(not_raised, conditional);
}

}  // namespace
