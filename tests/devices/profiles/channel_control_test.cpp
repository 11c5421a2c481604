// Channel device control on the object dictionary, frame level: control word by SDO, status word,
// mode locks (0x08000022), local control (0x08000021), PASO control. Node 1.
#include "devices/profiles/dsp408/channel_control.h"

#include <gtest/gtest.h>

#include <memory>

#include "devices/canopen/standard_objects.h"
#include "tests/support/canopen_harness.h"

using canopen::Access;
using canopen::DataType;
using vtest::Frame;
using vtest::Frames;

namespace {
canopen::ObjectDictionary make_od() {
  canopen::ObjectDictionary od;
  canopen::CommunicationProfile profile;
  profile.device_type = 0x198;
  canopen::add_communication_objects(od, profile);
  od.add_var(0x6040, "Control word", DataType::Unsigned16, Access::ReadWrite, 0, true);
  od.add_var(0x6041, "Status word", DataType::Unsigned16, Access::ReadOnly, 0, true);
  od.add_var(0x6042, "Device mode", DataType::Integer8, Access::ReadWrite, 1);
  od.add_var(0x6043, "Control mode", DataType::Integer8, Access::ReadWrite, 1);
  od.add_var(0x604F, "Device local", DataType::Integer8, Access::ReadWrite, 0);
  return od;
}

struct ChannelControlTest : ::testing::Test {
  ChannelControlTest() : h(make_od(), {}, 1) {
    channel = std::make_unique<dsp408::ChannelControl>(h.node().od(), dsp408::ChannelObjects{});
    channel->set_status_flags([this] { return dsp408::StatusFlags{.ramp_running = ramp}; });
    h.power_on();
    channel->power_on();
    h.take();
  }
  Frame sdo(std::initializer_list<std::uint8_t> bytes) { return *h.sdo(bytes); }
  vtest::CanopenHarness h;
  std::unique_ptr<dsp408::ChannelControl> channel;
  bool ramp = false;
};
Frame resp(std::initializer_list<std::uint8_t> bytes) { return Frame(0x581, bytes); }
}  // namespace

TEST_F(ChannelControlTest, ControlWordBySdoDrivesTheStateMachine) {
  EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), resp({0x4B, 0x41, 0x60, 0x00, 0x08, 0x00, 0x00, 0x00}));
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0}));
  ramp = true;
  EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), resp({0x4B, 0x41, 0x60, 0x00, 0x0F, 0x02, 0x00, 0x00}));
}

TEST_F(ChannelControlTest, ModesChangeOnlyInInitOrDisabled) {
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x03}), resp({0x60, 0x43, 0x60, 0x00, 0, 0, 0, 0}));
  h.write(0x6040, 0, 0x0003, 2);  // HOLD
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x01}), resp({0x80, 0x43, 0x60, 0x00, 0x22, 0x00, 0x00, 0x08}));
  EXPECT_EQ(sdo({0x2F, 0x42, 0x60, 0x00, 0x02}), resp({0x80, 0x42, 0x60, 0x00, 0x22, 0x00, 0x00, 0x08}));
  EXPECT_EQ(sdo({0x2F, 0x4F, 0x60, 0x00, 0x01}), resp({0x80, 0x4F, 0x60, 0x00, 0x22, 0x00, 0x00, 0x08}));
  EXPECT_EQ(h.node().od().get<std::int8_t>(0x6043), 3);
  h.write(0x6040, 0, 0x0001, 2);  // DISABLED
  EXPECT_EQ(sdo({0x2F, 0x43, 0x60, 0x00, 0x01}), resp({0x60, 0x43, 0x60, 0x00, 0, 0, 0, 0}));
}

TEST_F(ChannelControlTest, LocalControlRefusesControlWordsAndSetsBit4) {
  EXPECT_EQ(sdo({0x2F, 0x4F, 0x60, 0x00, 0x01}), resp({0x60, 0x4F, 0x60, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), resp({0x80, 0x40, 0x60, 0x00, 0x21, 0x00, 0x00, 0x08}));
  EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), resp({0x4B, 0x41, 0x60, 0x00, 0x18, 0x00, 0x00, 0x00}));
  channel->dsm().set_enable_input(false);
  channel->dsm().set_enable_input(true);
  EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), resp({0x4B, 0x41, 0x60, 0x00, 0x1F, 0x00, 0x00, 0x00}));
  channel->dsm().set_enable_input(false);
  EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), resp({0x4B, 0x41, 0x60, 0x00, 0x19, 0x00, 0x00, 0x00}));
  EXPECT_EQ(sdo({0x2F, 0x4F, 0x60, 0x00, 0x00}), resp({0x60, 0x4F, 0x60, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(sdo({0x40, 0x41, 0x60, 0x00}), resp({0x4B, 0x41, 0x60, 0x00, 0x09, 0x00, 0x00, 0x00}));
}

TEST_F(ChannelControlTest, PasoControlAcceptsLocalButRefusesBusOperation) {
  channel->set_paso_control(true);
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x07, 0x00}), resp({0x80, 0x40, 0x60, 0x00, 0x21, 0x00, 0x00, 0x08}));
  EXPECT_EQ(sdo({0x2F, 0x4F, 0x60, 0x00, 0x00}), resp({0x80, 0x4F, 0x60, 0x00, 0x21, 0x00, 0x00, 0x08}));
  EXPECT_EQ(sdo({0x2F, 0x4F, 0x60, 0x00, 0x01}), resp({0x60, 0x4F, 0x60, 0x00, 0, 0, 0, 0}));
  channel->set_paso_control(false);  // PASO gives control back: local (0x604F = 1) now applies
  EXPECT_EQ(channel->source(), dsp408::ControlSource::Local);
}

TEST_F(ChannelControlTest, LiveOnlyFlagsAreAskedInActiveAndHoldOnly) {
  int asked = 0;
  channel->set_status_flags(
      [&] {
        ++asked;
        return dsp408::StatusFlags{.ramp_running = true};
      },
      true);
  EXPECT_EQ(channel->status_word() & dsp408::status::kRampRunning, 0);
  EXPECT_EQ(asked, 0);
  h.write(0x6040, 0, 0x0007, 2);  // ACTIVE
  EXPECT_EQ(channel->state(), dsp408::DeviceState::Active);
  EXPECT_NE(channel->status_word() & dsp408::status::kRampRunning, 0);
  EXPECT_EQ(asked, 1);
  h.write(0x6040, 0, 0x0003, 2);  // HOLD
  EXPECT_EQ(channel->state(), dsp408::DeviceState::Hold);
  EXPECT_NE(channel->status_word() & dsp408::status::kRampRunning, 0);
  EXPECT_EQ(asked, 2);
  h.write(0x6040, 0, 0x0001, 2);  // DISABLED
  EXPECT_EQ(channel->status_word() & dsp408::status::kRampRunning, 0);
  EXPECT_EQ(asked, 2);
  channel->publish_status();  // the stored word follows the state, the flags not asked
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6041), channel->status_word());
  EXPECT_EQ(asked, 2);
}
