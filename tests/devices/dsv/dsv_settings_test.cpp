// The DSV's ports, fault names and settings validation.
#include "tests/devices/dsv/dsv_fixture.h"

namespace dsvtest {

TEST_F(DsvTest, PortsAndFaultNames) {
  const auto ports = dev->ports();
  for (const char* name : {"solenoid_a_current", "solenoid_b_current", "actual_value", "actual_cable_break",
                           "enable_input", "supply_voltage", "temperature"}) {
    EXPECT_NE(sim::find_port(ports, name), nullptr) << name;
  }
  EXPECT_EQ(dev->set_input("actual", 0.5), "");
  EXPECT_NE(dev->set_input("solenoid_a_current", 1), "");
  EXPECT_NE(dev->inject_fault("nosuch", true), "");
  for (const auto& f : dev->faults()) EXPECT_EQ(dev->inject_fault(f.name, false), "") << f.name;
  make(bus_mode({{"solenoids", "1"}, {"mode_of_operation", "0"}}));
  EXPECT_NE(dev->inject_fault("solenoid_b_open", true), "");
}

TEST_F(DsvTest, SupplyVoltagePort) {
  ASSERT_EQ(dev->set_input("supply_voltage", 17), "");
  h->run_ms(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x12, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(DsvTest, FactoryStateIsLocalWithoutControlMode) {
  make({});
  EXPECT_EQ(status(), 0x0018);  // "Local" and "Init"
  EXPECT_EQ(read(0x6043), 0);
  EXPECT_EQ(read_abort(0x2042), 0x06020000u);           // mode 0 has no mode of operation
  EXPECT_EQ(write(0x6043, 0, 1, 1), 0x08000021u);       // local operation holds the modes
  ASSERT_EQ(write(0x604F, 0, 0, 1), 0u);
  ASSERT_EQ(write(0x6043, 0, 1, 1), 0u);
  EXPECT_EQ(read(0x2042), 1);                           // printed default of 2042h
}

TEST_F(DsvTest, SettingsAreValidated) {
  for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{
           {"nosuch", "1"}, {"solenoids", "3"}, {"supply_voltage_nominal", "48"}, {"imin", "9000"},
           {"dither_amplitude", "5000"}, {"device_local", "2"}, {"sensor_max", "-1"}}) {
    devices::DeviceOptions o;
    o.settings[name] = value;
    std::string error;
    EXPECT_FALSE(dsv::Dsv::create(o, error)) << name;
    EXPECT_FALSE(error.empty());
  }
  devices::DeviceOptions o;
  o.settings["control_mode"] = "4";  // controller mode on the amplifier
  std::string error;
  EXPECT_FALSE(dsv::Dsv::create(o, error));
}

TEST_F(DsvTest, SettingOutputsNeedOperational) {
  make(bus_mode({{"outputs_need_operational", "true"}, {"dither_amplitude", "0"}}));
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6300, 1, 8192, 2), 0u);
  h->run_ms(1);
  EXPECT_EQ(dev->solenoid_a(), 0.0);
  start();
  h->run_ms(1);
  EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
}

TEST_F(DsvTest, SettingM4TpdoSixBytes) {
  make(bus_mode({{"control_mode", "4"}, {"m4_tpdo_six_bytes", "true"}}), "controller");
  EXPECT_EQ(read(0x1A01, 2), 0x63810020);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_EQ(h->take(), Frames{Frame(0x281, {0x0F, 0x00, 0x00, 0x00, 0x00, 0x00})});
}

TEST_F(DsvTest, SettingQuantiseOnWrite) {
  make(bus_mode({{"quantise_on_write", "true"}}));
  ASSERT_EQ(write(0x6343, 1, 2735, 2), 0u);
  EXPECT_EQ(read(0x6343, 1), 2720);  // steps of 16
  make(bus_mode());
  ASSERT_EQ(write(0x6343, 1, 2735, 2), 0u);
  EXPECT_EQ(read(0x6343, 1), 2735);
}

}  // namespace dsvtest
