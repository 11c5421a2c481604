// The MD2's knobs for the digest's [R] readings that change what the bus sees
// (docs/devices/md2.md, "Settings").
#include "tests/devices/md2/md2_fixture.h"

namespace md2test {

TEST_F(Md2Test, SettingVpocMappingLiteral) {
  make({{"vpoc_mapping_literal", "true"}, {"dither_level", "0"}}, "controller");  // delivered in mode 3
  EXPECT_EQ(read(0x1600, 2), 0x63000110u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});  // the pressure set point travels in 0x6300
  h->run_ms(1);
  h->take();
  EXPECT_NEAR(ch().solenoid_a, 0.6, 1e-9);
}

TEST_F(Md2Test, SettingTpdoActualValueAndDeviceType) {
  make({{"control_mode", "4"}, {"tpdo_actual_value", "false"}, {"device_type", "0x80000198"}}, "controller");
  EXPECT_EQ(read(0x1A00, 0), 1u);
  EXPECT_EQ(read(0x1000), 0x80000198u);
  make({{"control_mode", "4"}}, "controller");
  EXPECT_EQ(read(0x1A00, 0), 2u);
  EXPECT_EQ(read(0x1A00, 2), 0x63810110u);
}

TEST_F(Md2Test, SettingPdoParametersInOperational) {
  make({{"pdo_params_preop_only", "false"}});
  start();
  EXPECT_EQ(write(0x1800, 2, 1, 1), 0u);
}

TEST_F(Md2Test, SettingEmcyBeforeStop) {
  make({{"emcy_before_stop", "true"}});
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  h->nmt(0x02, 1);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00})});
  h->nmt(0x80, 1);
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(read(0x1003), 1u);  // one event, not two
}

TEST_F(Md2Test, SettingOutputsNeedOperational) {
  make({{"outputs_need_operational", "true"}, {"dither_level", "0"}});
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6300, 1, 8192, 2), 0u);
  h->run_ms(1);
  EXPECT_EQ(ch().solenoid_a, 0.0);
  start();
  h->run_ms(1);
  EXPECT_NEAR(ch().solenoid_a, 0.6, 1e-9);
}

TEST_F(Md2Test, SettingIdentityRevisionAndSerial) {
  make({{"identity_entries", "4"}, {"identity_revision", "0x00010002"}, {"identity_serial", "123456"}});
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x03}), Frames{resp({0x43, 0x18, 0x10, 0x03, 0x02, 0x00, 0x01, 0x00})});
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x04}), Frames{resp({0x43, 0x18, 0x10, 0x04, 0x40, 0xE2, 0x01, 0x00})});
  make({{"identity_entries", "4"}});  // default: 0
  EXPECT_EQ(sdo({0x40, 0x18, 0x10, 0x03}), Frames{resp({0x43, 0x18, 0x10, 0x03, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(Md2Test, SettingTpdo255OnChange) {
  // Default: a type-255 TPDO goes out only after its RPDO, not when the status word changes.
  start();
  auto frames = sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00});
  h->run_ms(2);
  for (const auto& f : h->take()) frames.push_back(f);
  EXPECT_EQ(frames, Frames{resp({0x60, 0x40, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00})});
  // Option: also sent when the mapped data change (first time at once in Operational).
  make({{"tpdo255_on_change", "true"}, {"channels", "1"}});  // TPDO2-4 disabled
  h->nmt(0x01, 0);
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x08, 0x00})});
  frames = sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00});
  h->run_ms(2);
  for (const auto& f : h->take()) frames.push_back(f);
  EXPECT_EQ(frames, (Frames{resp({0x60, 0x40, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00}), Frame(0x181, {0x0F, 0x00})}));
  h->run_ms(10);
  EXPECT_EQ(h->take(), Frames{});  // no change, no frame
}

TEST_F(Md2Test, SettingSpeedModes) {
  // Mode 9 with Speed+ 10 mm/s: rate-limited by default, not with speed_modes=6,7.
  const auto run = [this](std::map<std::string, std::string> settings) {
    settings["dither_level"] = "0";
    settings["unit"] = "mm/s";
    settings["deadband_modes"] = "open_loop";
    make(settings, "controller");
    EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x09}), Frames{resp({0x60, 0x43, 0x60, 0x00, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x23, 0x00, 0x24, 0x00, 0x10, 0x27, 0x00, 0x00}), Frames{resp({0x60, 0x00, 0x24, 0x00, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x23, 0x00, 0x66, 0x01, 0xA0, 0x86, 0x01, 0x00}), Frames{resp({0x60, 0x00, 0x66, 0x01, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), Frames{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})});
    h->run_ms(500);
    return ch().solenoid_a;
  };
  EXPECT_NEAR(run({}), 0.2 + 0.8 * 5000 / 2e6, 1e-5);                       // r = 5000 after 0.5 s
  EXPECT_NEAR(run({{"speed_modes", "6,7"}}), 0.2 + 0.8 * 100000 / 2e6, 1e-9);  // r = w at once
}

TEST_F(Md2Test, SettingDeadbandModes) {
  // Mode 9, deviation 1000 of 2000000 (u = 0.0005, inside the 1 % dead band).
  const auto run = [this](std::map<std::string, std::string> settings) {
    settings["dither_level"] = "0";
    make(settings, "controller");
    EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x09}), Frames{resp({0x60, 0x43, 0x60, 0x00, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x2F, 0x00, 0x22, 0x00, 0x01}), Frames{resp({0x60, 0x00, 0x22, 0x00, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x23, 0x00, 0x66, 0x01, 0xA0, 0x86, 0x01, 0x00}), Frames{resp({0x60, 0x00, 0x66, 0x01, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x23, 0x02, 0x22, 0x00, 0xB8, 0x82, 0x01, 0x00}), Frames{resp({0x60, 0x02, 0x22, 0x00, 0, 0, 0, 0})});
    EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), Frames{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})});
    h->run_ms(2);
    EXPECT_EQ(sdo({0x40, 0x50, 0x66, 0x01}), Frames{resp({0x43, 0x50, 0x66, 0x01, 0xE8, 0x03, 0x00, 0x00})});
    return ch().solenoid_a;
  };
  EXPECT_EQ(run({}), 0.0);  // digest §5.1 step 5: the dead band in every mode
  EXPECT_NEAR(run({{"deadband_modes", "open_loop"}}), 0.2 + 0.8 * 1000 / 2e6, 1e-9);
}

TEST_F(Md2Test, SettingsAreValidated) {
  for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{
           {"nosuch", "1"}, {"channels", "9"}, {"kp", "fast"}, {"i_min_a", "2"}, {"unit", "furlong"},
           {"dither_shape", "triangle"}, {"solenoids", "3"},
           {"speed_modes", "1"}, {"speed_modes", "6,x"}, {"deadband_modes", "closed"}, {"identity_serial", "abc"}}) {
    devices::DeviceOptions o;
    o.settings[name] = value;
    std::string error;
    EXPECT_FALSE(md2::Md2Device::create(o, error)) << name;
    EXPECT_FALSE(error.empty());
  }
  devices::DeviceOptions o;
  o.variant = "pump";
  std::string error;
  EXPECT_FALSE(md2::Md2Device::create(o, error));
  o.variant = "";
  o.settings["control_mode"] = "9";  // the amplifier has no mode 9
  EXPECT_FALSE(md2::Md2Device::create(o, error));
}

TEST_F(Md2Test, PortsAndFaultNames) {
  const auto ports = dev->ports();
  EXPECT_NE(sim::find_port(ports, "ch1.solenoid_a_current"), nullptr);
  EXPECT_NE(sim::find_port(ports, "ch8.solenoid_b_current"), nullptr);
  EXPECT_EQ(sim::find_port(ports, "ch1.actual_value"), nullptr);  // amplifier: no feedback
  EXPECT_EQ(dev->set_input("ch1.solenoid_a_current", 1), "port 'ch1.solenoid_a_current' is an output");
  make({}, "controller");
  EXPECT_NE(sim::find_port(dev->ports(), "ch4.actual_value"), nullptr);
  EXPECT_EQ(sim::find_port(dev->ports(), "ch5.actual_value"), nullptr);
  EXPECT_EQ(dev->set_input("actual", 2.5), "");
  EXPECT_EQ(ch().actual_value, 2.5);
  EXPECT_NE(dev->inject_fault("nosuch", true), "");
  for (const auto& f : dev->faults()) EXPECT_EQ(dev->inject_fault(f.name, false), "") << f.name;
}

// The control plane sees each channel's state machine through Device, not through the MD2 type.
TEST_F(Md2Test, SettingChannelsAreTheProfileChannels) {
  devices::Device& device = *dev;
  ASSERT_EQ(device.profile_channel_count(), 8);  // the factory default
  EXPECT_EQ(device.channel_profile_status(1).state, device.profile_status().state);
  EXPECT_EQ(device.channel_profile_status(8).profile, devices::ProfileStatus::Profile::Dsp408);
  EXPECT_EQ(device.channel_profile_status(9).profile, devices::ProfileStatus::Profile::Generic);
  EXPECT_EQ(device.channel_profile_status(0).profile, devices::ProfileStatus::Profile::Generic);
  make({{"channels", "1"}});
  EXPECT_EQ(dev->profile_channel_count(), 1);
  EXPECT_EQ(dev->channel_profile_status(2).profile, devices::ProfileStatus::Profile::Generic);
}

}  // namespace md2test
