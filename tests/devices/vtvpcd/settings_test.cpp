// Configuration: the documented defaults, rejected names and values, and the Bus Manager areas.
#include "devices/vtvpcd/settings.h"

#include <gtest/gtest.h>

#include "devices/vtvpcd/bus_manager_areas.h"

using namespace vtvpcd;

TEST(Settings, DocumentedDefaultsParseToTheDefaultSettings) {
  std::map<std::string, std::string> all;
  for (const auto& [name, text] : Settings::defaults()) all[name] = text;
  Settings parsed, defaults;
  std::string error;
  ASSERT_TRUE(Settings::parse(all, parsed, error)) << error;
  EXPECT_EQ(parsed.boot_delay_ms, defaults.boot_delay_ms);
  EXPECT_EQ(parsed.areas.from_card, defaults.areas.from_card);
  EXPECT_EQ(parsed.areas.to_card, defaults.areas.to_card);
  EXPECT_EQ(parsed.do_functions, defaults.do_functions);
  EXPECT_EQ(parsed.p_ref_bar, defaults.p_ref_bar);
  EXPECT_EQ(parsed.plant.k_load, defaults.plant.k_load);
  EXPECT_EQ(parsed.pump_type, defaults.pump_type);
  EXPECT_EQ(parsed.controlled_pressure, ControlledPressure::FlowSide);
  EXPECT_EQ(defaults.controlled_pressure, ControlledPressure::FlowSide);
  EXPECT_EQ(parsed.timeout_reaction, defaults.timeout_reaction);
  EXPECT_TRUE(parsed.builtin_plant);
  EXPECT_GE(all.size(), 40u);
}

TEST(Settings, RejectsUnknownNamesAndBadValues) {
  Settings s;
  std::string error;
  EXPECT_FALSE(Settings::parse({{"no_such_knob", "1"}}, s, error));
  EXPECT_NE(error.find("unknown setting 'no_such_knob'"), std::string::npos);
  for (const auto& [name, value] :
       std::vector<std::pair<std::string, std::string>>{{"sdo_size_mode", "loose"},
                                                        {"boot_delay_ms", "-1"},
                                                        {"reset_boot_delay_ms", "101"},
                                                        {"pump_type", "A10V"},
                                                        {"controlled_pressure", "both"},
                                                        {"p_ref_bar", "0"},
                                                        {"k_pos", "abc"},
                                                        {"node_id_object", "0x2C72"},  // a chapter-4 object
                                                        {"node_id_object", "0x6000"},
                                                        {"do_functions", "ok"},
                                                        {"tpdo_area", "0x2F0F"},
                                                        {"tpdo_area", "0x3000:4"},           // not a parameter
                                                        {"rpdo_area", "0x2F07:4"},           // read-only to the card
                                                        {"rpdo_area", "0x2C72:3"},           // 2 or 4 bytes only
                                                        {"tpdo_area", "0x2F26:2,0x2F0F:4,0x2F19:4"},  // straddles
                                                        {"scale_0x2F0E", "300"}}) {
    Settings t;
    EXPECT_FALSE(Settings::parse({{name, value}}, t, error)) << name << "=" << value;
    EXPECT_FALSE(error.empty());
  }
}

TEST(Settings, AreaStraddlePadStartsTheEntryInTheNextPdo) {
  Settings s;
  std::string error;
  ASSERT_TRUE(Settings::parse({{"tpdo_area", "0x2F26:2,0x2F0F:4,0x2F19:4"}, {"area_straddle", "pad"}}, s, error)) << error;
  BusManagerAreas::Mapping m;
  ASSERT_TRUE(s.areas.to_mapping(m, error));
  EXPECT_EQ(m.tpdo[0], (std::vector<std::uint32_t>{0x2F260010, 0x2F0F0020}));
  EXPECT_EQ(m.tpdo[1], (std::vector<std::uint32_t>{0x2F190020}));
}

TEST(BusManagerAreas, ManualExampleSplitsIntoTheDs301Mapping) {
  // Digest §2.9: 0x1600 = {0x2C670020, 0x2C740020}, 0x1601 = {0x2C720020, 0x20460020},
  // 0x1A00 = {0x2F0F0020, 0x2F260020}, 0x1A01 = {0x2F190020}; PDO 3 and 4 empty.
  BusManagerAreas::Mapping m;
  std::string error;
  ASSERT_TRUE(BusManagerAreas::manual_example().to_mapping(m, error)) << error;
  EXPECT_EQ(m.rpdo[0], (std::vector<std::uint32_t>{0x2C670020, 0x2C740020}));
  EXPECT_EQ(m.rpdo[1], (std::vector<std::uint32_t>{0x2C720020, 0x20460020}));
  EXPECT_TRUE(m.rpdo[2].empty());
  EXPECT_TRUE(m.rpdo[3].empty());
  EXPECT_EQ(m.tpdo[0], (std::vector<std::uint32_t>{0x2F0F0020, 0x2F260020}));
  EXPECT_EQ(m.tpdo[1], (std::vector<std::uint32_t>{0x2F190020}));
  EXPECT_TRUE(m.tpdo[2].empty());
}

TEST(BusManagerAreas, ThirtyTwoBytesAtMost) {
  std::vector<AreaEntry> area;
  std::string error;
  ASSERT_TRUE(parse_area("0x2F07:4,0x2F10:4,0x2F0F:4,0x2F19:4,0x2F33:4,0x2C72:4,0x2F03:4,0x2F1A:4", area, error));
  BusManagerAreas a;
  a.from_card = area;
  BusManagerAreas::Mapping m;
  EXPECT_TRUE(a.to_mapping(m, error)) << error;
  EXPECT_EQ(m.tpdo[3].size(), 2u);
  a.from_card.push_back({0x2F27, 2});
  EXPECT_FALSE(a.to_mapping(m, error));
  EXPECT_EQ(format_area(BusManagerAreas::manual_example().from_card), "0x2F0F:4,0x2F26:4,0x2F19:4");
}
