// Configuration: the documented defaults, rejected names and values, and the Bus Manager areas.
#include "devices/vtvpcd/settings.h"

#include <gtest/gtest.h>

#include "devices/vtvpcd/bus_manager_areas.h"

using namespace vtvpcd;

TEST(Settings, EverySettingIsReadIntoItsField) {
  Settings s;
  std::string error;
  ASSERT_TRUE(Settings::parse({{"boot_delay_ms", "500"},
                               {"nmt_stop_supported", "false"},
                               {"sdo_size_mode", "strict"},
                               {"nmt_82", "can_controller"},
                               {"node_id_object", "0x4000"},
                               {"vendor_id", "0x12345678"},
                               {"tpdo_area", "0x2F0F:4"},
                               {"area_straddle", "pad"},
                               {"pump_type", "A2V"},
                               {"controlled_pressure", "max"},
                               {"scale_0x2F0E", "324.7"},
                               {"timeout_reaction", "report"},
                               {"do_functions", "off,off,slave,off,off,off,angle_window"},
                               {"p_ref_bar", "280"},
                               {"x_off_pct", "-10"},
                               {"k_load", "0"},
                               {"pilot_supply", "internal"}},
                              s, error))
      << error;
  EXPECT_EQ(s.boot_delay_ms, 500);
  EXPECT_FALSE(s.nmt_stop_supported);
  EXPECT_TRUE(s.sdo_size_strict);
  EXPECT_TRUE(s.reset_communication_keeps_parameters);
  EXPECT_EQ(s.node_id_object, 0x4000);
  EXPECT_EQ(s.identity[0], 0x12345678u);
  EXPECT_EQ(format_area(s.areas.from_card), "0x2F0F:4");
  EXPECT_EQ(s.areas.straddle, Straddle::Pad);
  EXPECT_EQ(s.pump_type, PumpType::A2V);
  EXPECT_EQ(s.controlled_pressure, ControlledPressure::Max);
  EXPECT_TRUE(s.press_cmd_scale_printed);
  EXPECT_EQ(s.timeout_reaction, TimeoutReaction::Report);
  EXPECT_EQ(s.do_functions[2], OutputFunction::SlaveMode);
  EXPECT_EQ(s.do_functions[6], OutputFunction::AngleWindow);
  EXPECT_EQ(s.p_ref_bar, 280.0);
  EXPECT_EQ(s.x_off_pct, -10.0);
  EXPECT_EQ(s.plant.k_load, 0.0);
  EXPECT_EQ(s.plant.pilot_supply, PilotSupply::Internal);

  // Nothing given: the defaults the struct documents, and the manual's example areas.
  Settings none, defaults;
  ASSERT_TRUE(Settings::parse({}, none, error)) << error;
  EXPECT_EQ(none.areas.from_card, BusManagerAreas::manual_example().from_card);
  EXPECT_EQ(none.do_functions, defaults.do_functions);
  EXPECT_EQ(none.controlled_pressure, ControlledPressure::FlowSide);
}

TEST(Settings, ErrorsAreWordedAsEveryProducts) {
  Settings s;
  std::string error;
  EXPECT_FALSE(Settings::parse({{"p_ref_bar", "0"}}, s, error));
  EXPECT_EQ(error, "setting p_ref_bar: value 0 out of range (0, 600]");
  EXPECT_FALSE(Settings::parse({{"boot_delay_ms", "70000"}}, s, error));
  EXPECT_EQ(error, "setting boot_delay_ms: value 70000 out of range [0, 60000]");
  EXPECT_FALSE(Settings::parse({{"pump_type", "A10V"}}, s, error));
  EXPECT_EQ(error, "setting pump_type='A10V': expected A4VSO | A4VSG | A2V");
  EXPECT_FALSE(Settings::parse({{"node_id_object", "0x2C72"}}, s, error));
  EXPECT_EQ(error, "setting node_id_object='0x2C72': expected none or a free index 0x2000..0x5FFF (not a chapter-4 object)");
  EXPECT_FALSE(Settings::parse({{"pump", "A2V"}}, s, error));
  EXPECT_NE(error.find("unknown setting 'pump' (known: "), std::string::npos) << error;
  EXPECT_NE(error.find("pump_type"), std::string::npos) << error;
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
