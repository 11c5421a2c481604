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

TEST_F(DsvTest, SettingRestoreKeepsAddress) {
  // node address 5 saved, then "restore all defaults" and Reset Node.
  for (const bool keep : {false, true}) {
    make(bus_mode({{"restore_keeps_address", keep ? "true" : "false"}}), "", 0, temp_store(keep ? "a18k" : "a18"));
    ASSERT_EQ(write(0x2000, 0, 5, 1), 0u);
    ASSERT_EQ(write(0x1010, 1, 0x65766173, 4), 0u);
    EXPECT_EQ(sdo({0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64}), Frames{resp({0x60, 0x11, 0x10, 0x01, 0, 0, 0, 0})});
    h->nmt(0x81, 1);
    h->run_ms(5);
    if (keep) {
      EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x00})});
      h->send(0x605, {0x40, 0x43, 0x60, 0x00, 0, 0, 0, 0});  // the rest is restored: 6043h = 0
      EXPECT_EQ(h->take(), Frames{Frame(0x585, {0x4F, 0x43, 0x60, 0x00, 0x00, 0x00, 0x00, 0x00})});
    } else {
      EXPECT_EQ(h->take(), Frames{Frame(0x701, {0x00})});  // back to node 1
    }
  }
}

TEST_F(DsvTest, SettingAlias230eInMode7) {
  make(bus_mode({{"control_mode", "7"}}), "controller");
  EXPECT_EQ(sdo({0x40, 0x0E, 0x23, 0x01}), Frames{resp({0x80, 0x0E, 0x23, 0x01, 0x00, 0x00, 0x02, 0x06})});
  make(bus_mode({{"control_mode", "7"}, {"alias_230e_mode7", "true"}}), "controller");
  EXPECT_EQ(sdo({0x23, 0x0E, 0x23, 0x01, 0xD2, 0x04, 0x00, 0x00}), Frames{resp({0x60, 0x0E, 0x23, 0x01, 0, 0, 0, 0})});
  EXPECT_EQ(sdo({0x40, 0x0E, 0x25, 0x01}), Frames{resp({0x43, 0x0E, 0x25, 0x01, 0xD2, 0x04, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x23, 0x0E, 0x25, 0x01, 0x39, 0x30, 0x00, 0x00}), Frames{resp({0x60, 0x0E, 0x25, 0x01, 0, 0, 0, 0})});
  EXPECT_EQ(sdo({0x40, 0x0E, 0x23, 0x01}), Frames{resp({0x43, 0x0E, 0x23, 0x01, 0x39, 0x30, 0x00, 0x00})});
  h->run_ms(1);
  // In mode 4, 230Eh is its own object again and kept its value (0).
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x04}), Frames{resp({0x60, 0x43, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(sdo({0x40, 0x0E, 0x23, 0x01}), Frames{resp({0x43, 0x0E, 0x23, 0x01, 0x00, 0x00, 0x00, 0x00})});
  EXPECT_EQ(sdo({0x40, 0x0E, 0x25, 0x01}), Frames{resp({0x80, 0x0E, 0x25, 0x01, 0x00, 0x00, 0x02, 0x06})});
}

TEST_F(DsvTest, SettingFaultHold) {
  // Mode 1, bipolar, 50 %: ACTIVE, then a general error.
  for (const bool hold : {false, true}) {
    make(bus_mode({{"fault_hold", hold ? "true" : "false"}, {"dither_amplitude", "0"}}));
    ASSERT_EQ(write(0x6300, 1, 8192, 2), 0u);
    EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), Frames{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})});
    h->run_ms(1);
    ASSERT_EQ(dev->inject_fault("general_error", true), "");
    h->run_ms(1);
    EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x00, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00})});
    EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), Frames{resp({0x4B, 0x41, 0x60, 0x00, static_cast<std::uint8_t>(hold ? 0x03 : 0x01), 0x00, 0, 0})});
    h->run_ms(5);
    if (hold) {
      EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);  // FAULT_HOLD keeps the hold set point
    } else {
      EXPECT_EQ(dev->solenoid_a(), 0.0);  // 2043h = 0
    }
    ASSERT_EQ(dev->inject_fault("general_error", false), "");
    h->run_ms(1);
    EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00}),
              (Frames{Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})}));
    h->run_ms(1);
    EXPECT_EQ(status(), 0x000F);  // TR_11 → HOLD → TR_4
    EXPECT_NEAR(dev->solenoid_a(), amps(0.5), 1e-9);
  }
}

TEST_F(DsvTest, SettingStrictFaultReset) {
  // From FAULT an R edge with H = 1 (0x0007 → 0x000F): TR_11 by default, nothing when strict.
  for (const bool strict : {false, true}) {
    make(bus_mode({{"strict_fault_reset", strict ? "true" : "false"}}));
    EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), Frames{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})});
    ASSERT_EQ(dev->inject_fault("general_error", true), "");
    h->run_ms(1);
    ASSERT_EQ(dev->inject_fault("general_error", false), "");
    h->run_ms(1);
    h->take();
    Frames expected{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})};
    if (!strict) expected.insert(expected.begin(), Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}));  // reset: "no error"
    EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00}), expected);
    EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), Frames{resp({0x4B, 0x41, 0x60, 0x00, static_cast<std::uint8_t>(strict ? 0x01 : 0x0F), 0x00, 0, 0})});
  }
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x01, 0x00}), Frames{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x09, 0x00}),  // TR_10 from FAULT
            (Frames{Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})}));
  EXPECT_EQ(status(), 0x0009);
}

TEST_F(DsvTest, SettingPdoPadding) {
  // TV-40 with A-50's option: the 2-byte TPDO1 goes out as the manual's 8-byte drawing.
  make(bus_mode({{"pdo_padding", "true"}}));
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x20});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00, 0, 0, 0, 0, 0, 0})});
}

TEST_F(DsvTest, SettingsAreValidated) {
  for (const auto& [name, value] : std::vector<std::pair<std::string, std::string>>{
           {"nosuch", "1"}, {"solenoids", "3"}, {"supply_voltage_nominal", "48"}, {"imin", "9000"},
           {"dither_amplitude", "5000"}, {"device_local", "2"}, {"sensor_max", "-1"},
           {"fault_hold", "maybe"}, {"alias_230e_mode7", "2"}}) {
    devices::DeviceOptions o;
    o.settings[name] = value;
    std::string error;
    EXPECT_FALSE(dsv::DsvDevice::create(o, error)) << name;
    EXPECT_FALSE(error.empty());
  }
  devices::DeviceOptions o;
  o.settings["control_mode"] = "4";  // controller mode on the amplifier
  std::string error;
  EXPECT_FALSE(dsv::DsvDevice::create(o, error));
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
