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
  make({{"nv_control_mode", "4"}, {"tpdo_actual_value", "false"}, {"device_type", "0x80000198"}}, "controller");
  EXPECT_EQ(read(0x1A00, 0), 1u);
  EXPECT_EQ(read(0x1000), 0x80000198u);
  make({{"nv_control_mode", "4"}}, "controller");
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

TEST_F(Md2Test, SettingsAreValidated) {
  for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{
           {"nosuch", "1"}, {"channels", "9"}, {"kp", "fast"}, {"i_min_a", "2"}, {"unit", "furlong"},
           {"dither_shape", "triangle"}, {"solenoids", "3"}}) {
    devices::DeviceOptions o;
    o.settings[name] = value;
    std::string error;
    EXPECT_FALSE(md2::Md2::create(o, error)) << name;
    EXPECT_FALSE(error.empty());
  }
  devices::DeviceOptions o;
  o.variant = "pump";
  std::string error;
  EXPECT_FALSE(md2::Md2::create(o, error));
  o.variant = "";
  o.settings["nv_control_mode"] = "9";  // the amplifier has no mode 9
  EXPECT_FALSE(md2::Md2::create(o, error));
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

}  // namespace md2test
