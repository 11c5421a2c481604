// The DSP 408 device state machine: transition table of the MD2/DSV manuals §5.2.2, chained
// transitions, the reset-fault edge and the enable input.
#include "devices/profiles/dsp408/device_state_machine.h"

#include <gtest/gtest.h>

#include <vector>

using dsp408::DeviceState;
using dsp408::DeviceStateMachine;
using dsp408::state_bits;

namespace {
struct Fixture : ::testing::Test {
  Fixture() {
    dsm.set_listener([this](DeviceState from, DeviceState to) { log.push_back({from, to}); });
    dsm.set_fault_reset([this] { return !error_present; });
    dsm.power_on();
    log.clear();
  }
  std::uint16_t sw() const { return state_bits(dsm.state()); }
  DeviceStateMachine dsm;
  bool error_present = false;
  std::vector<std::pair<DeviceState, DeviceState>> log;
};
}  // namespace

TEST_F(Fixture, PowerOnIsInitWithStatus0008) { EXPECT_EQ(sw(), 0x8); }

TEST_F(Fixture, OneWriteOf0007ChainsTr2Tr3Tr4) {
  dsm.write_control_word(0x0007);
  EXPECT_EQ(dsm.state(), DeviceState::Active);
  EXPECT_EQ(sw(), 0xF);
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(log[0].second, DeviceState::Disabled);
  EXPECT_EQ(log[1].second, DeviceState::Hold);
  EXPECT_EQ(log[2].second, DeviceState::Active);
}

TEST_F(Fixture, ControlWordSequenceFromTheChecklist) {
  dsm.write_control_word(0x0007);
  const std::pair<std::uint16_t, std::uint16_t> steps[] = {{0x0003, 0xB}, {0x0001, 0x9}, {0x0000, 0x8},
                                                           {0x0001, 0x9}, {0x0003, 0xB}, {0x0007, 0xF}};
  for (auto [cw, expected] : steps) {
    dsm.write_control_word(cw);
    EXPECT_EQ(sw(), expected) << "cw " << cw;
  }
  dsm.write_control_word(0x0000);  // TR_5, TR_6, TR_7 in one write
  EXPECT_EQ(sw(), 0x8);
}

TEST_F(Fixture, PatternsWithoutATransitionLeaveTheStateAlone) {
  dsm.write_control_word(0x0006);  // INIT: D = 0
  EXPECT_EQ(dsm.state(), DeviceState::Init);
  dsm.write_control_word(0x0002);
  EXPECT_EQ(dsm.state(), DeviceState::Init);
  dsm.write_control_word(0x0007);
  dsm.write_control_word(0x0005);  // ACTIVE, M = 1, H = 0: no row matches
  EXPECT_EQ(dsm.state(), DeviceState::Active);
  dsm.write_control_word(0x0003);
  dsm.write_control_word(0x0002);  // HOLD: TR_6 needs H = 0
  EXPECT_EQ(dsm.state(), DeviceState::Hold);
  dsm.write_control_word(0x0004);  // HOLD, M = 1 without D, H: no row matches
  EXPECT_EQ(dsm.state(), DeviceState::Hold);
  // Reserved and manufacturer bits are ignored.
  dsm.write_control_word(0x8FF7);
  EXPECT_EQ(dsm.state(), DeviceState::Active);
}

TEST_F(Fixture, ErrorGoesThroughFaultReactionToFault) {
  dsm.write_control_word(0x0007);
  log.clear();
  EXPECT_TRUE(dsm.error());
  EXPECT_EQ(sw(), 0x1);
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0].second, DeviceState::FaultReaction);
  EXPECT_EQ(log[1].second, DeviceState::Fault);
  EXPECT_FALSE(dsm.error());  // already in FAULT
  // Control words without a reset edge do nothing in FAULT.
  dsm.write_control_word(0x0007);
  dsm.write_control_word(0x0000);
  EXPECT_EQ(dsm.state(), DeviceState::Fault);
}

TEST_F(Fixture, FaultResetNeedsARisingEdgeAndNoErrorPresent) {
  dsm.write_control_word(0x0001);
  dsm.error();
  error_present = true;
  dsm.write_control_word(0x0009);  // edge, but the error is still there
  EXPECT_EQ(dsm.state(), DeviceState::Fault);
  error_present = false;
  dsm.write_control_word(0x0009);  // no new edge
  EXPECT_EQ(dsm.state(), DeviceState::Fault);
  dsm.write_control_word(0x0001);
  dsm.write_control_word(0x0009);  // TR_10
  EXPECT_EQ(sw(), 0x9);
}

TEST_F(Fixture, FaultResetWithHoldEnableGoesToHoldAndChainsOn) {
  dsm.write_control_word(0x0007);
  dsm.error();
  dsm.write_control_word(0x000F);  // R edge with H = 1: TR_11 → HOLD → TR_4 → ACTIVE
  EXPECT_EQ(sw(), 0xF);
  dsm.error();
  dsm.write_control_word(0x0000);
  dsm.write_control_word(0x0008);  // TR_10 → DISABLED → TR_7 → INIT
  EXPECT_EQ(sw(), 0x8);
}

TEST_F(Fixture, FaultFromInitForHardwareErrorsButForcedFaultsSkipInit) {
  EXPECT_FALSE(dsm.forced_fault(false));
  EXPECT_EQ(dsm.state(), DeviceState::Init);
  EXPECT_TRUE(dsm.forced_fault(true));
  EXPECT_EQ(dsm.state(), DeviceState::Fault);
  dsm.power_on();
  EXPECT_TRUE(dsm.error());
  EXPECT_EQ(dsm.state(), DeviceState::Fault);
}

TEST_F(Fixture, EnableInputBlocksTr2AndItsFallingEdgeForcesInit) {
  dsm.set_enable_input(false);
  dsm.write_control_word(0x0007);
  EXPECT_EQ(dsm.state(), DeviceState::Init);
  dsm.set_enable_input(true);  // the stored control word is evaluated again
  EXPECT_EQ(dsm.state(), DeviceState::Active);
  dsm.set_enable_input(false);  // TR_567
  EXPECT_EQ(dsm.state(), DeviceState::Init);
}

TEST_F(Fixture, ActiveNeedsAControlMode) {
  dsm.set_active_allowed(false);
  dsm.write_control_word(0x0007);
  EXPECT_EQ(dsm.state(), DeviceState::Hold);
  dsm.set_active_allowed(true);
  dsm.write_control_word(0x0007);
  EXPECT_EQ(dsm.state(), DeviceState::Active);
}

TEST_F(Fixture, LocalOperationFollowsTheEnableInputEdges) {
  dsm.set_local(true);
  dsm.write_control_word(0x0007);  // ignored in local operation
  EXPECT_EQ(dsm.state(), DeviceState::Init);
  dsm.set_enable_input(false);
  EXPECT_EQ(dsm.state(), DeviceState::Init);
  dsm.set_enable_input(true);
  EXPECT_EQ(dsm.state(), DeviceState::Active);
  dsm.set_enable_input(false);
  EXPECT_EQ(dsm.state(), DeviceState::Disabled);
}

TEST_F(Fixture, FaultHoldOptionTakesTr9) {
  dsm.set_fault_hold(true);
  dsm.write_control_word(0x0007);
  log.clear();
  EXPECT_TRUE(dsm.error());
  EXPECT_EQ(sw(), 0x3);
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[1].second, DeviceState::FaultHold);
  EXPECT_FALSE(dsm.error());
  dsm.write_control_word(0x000F);  // TR_11 → HOLD → TR_4
  EXPECT_EQ(dsm.state(), DeviceState::Active);
}

TEST_F(Fixture, StrictResetSourcesOption) {
  dsm.set_strict_reset_sources(true);
  dsm.write_control_word(0x0007);
  dsm.error();                       // FAULT
  dsm.write_control_word(0x000F);    // R edge with H = 1: TR_11 needs FAULT_HOLD
  EXPECT_EQ(dsm.state(), DeviceState::Fault);
  dsm.write_control_word(0x0001);
  dsm.write_control_word(0x0009);    // TR_10
  EXPECT_EQ(sw(), 0x9);
  dsm.set_fault_hold(true);
  dsm.error();                       // FAULT_HOLD
  dsm.write_control_word(0x0001);
  dsm.write_control_word(0x0009);    // R edge with H = 0: TR_10 needs FAULT
  EXPECT_EQ(dsm.state(), DeviceState::FaultHold);
  dsm.write_control_word(0x0003);
  dsm.write_control_word(0x000B);    // TR_11
  EXPECT_EQ(sw(), 0xB);
}

// ---- the transition log: each step on its own, named as the manual names it, with its cause ----

namespace {
struct Recorded : ::testing::Test {
  Recorded() {
    dsm.set_recorder("dsp408", [this](const devices::Transition& t) { log.push_back(t); });
    dsm.power_on();
  }
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    for (const auto& t : log) out.push_back(t.transition);
    return out;
  }
  DeviceStateMachine dsm;
  std::vector<devices::Transition> log;
};
using Names = std::vector<std::string_view>;
}  // namespace

TEST_F(Recorded, PowerOnIsTr0FromOffThenTr1) {
  EXPECT_EQ(names(), (Names{"TR_0", "TR_1"}));
  EXPECT_EQ(log[0].from, "OFF");
  EXPECT_EQ(log[0].to, "NOT_READY");
  EXPECT_EQ(log[1].to, "INIT");
  EXPECT_EQ(log[0].cause, devices::TransitionCause::Boot);
  EXPECT_EQ(log[0].machine, "dsp408");
}

TEST_F(Recorded, ZeroInActiveIsTr5Tr6Tr7WithTheControlWord) {
  dsm.write_control_word(0x0007, "RPDO");
  log.clear();
  dsm.write_control_word(0x0000, "SDO");
  ASSERT_EQ(names(), (Names{"TR_5", "TR_6", "TR_7"}));
  for (const auto& t : log) {
    EXPECT_EQ(t.cause, devices::TransitionCause::ControlWord);
    EXPECT_EQ(t.value, 0u);
    EXPECT_EQ(t.detail, "SDO");
  }
  EXPECT_EQ(log[0].from, "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(log[2].to, "INIT");
}

TEST_F(Recorded, ForcedInitIsTr567WithTheCallersCause) {
  dsm.write_control_word(0x0007);
  log.clear();
  dsm.force_init({devices::TransitionCause::NmtCommand, 0x81, "the master"});
  ASSERT_EQ(names(), (Names{"TR_567"}));
  EXPECT_EQ(log[0].cause, devices::TransitionCause::NmtCommand);
  EXPECT_EQ(log[0].value, 0x81u);
  dsm.write_control_word(0x0007);
  log.clear();
  dsm.set_enable_input(false);
  ASSERT_EQ(names(), (Names{"TR_567"}));
  EXPECT_EQ(log[0].cause, devices::TransitionCause::Input);
  EXPECT_EQ(log[0].detail, "enable input");
}

TEST_F(Recorded, ErrorIsTr8Tr12WithTheEmcyCodeAndResetIsTr10) {
  dsm.write_control_word(0x0001);
  log.clear();
  dsm.error({devices::TransitionCause::DeviceFault, 0x5000, {}});
  ASSERT_EQ(names(), (Names{"TR_8", "TR_12"}));
  EXPECT_EQ(log[1].to, "FAULT");
  EXPECT_EQ(log[0].value, 0x5000u);
  log.clear();
  dsm.write_control_word(0x0009);  // R edge, H = 0
  ASSERT_EQ(names(), (Names{"TR_10"}));
  EXPECT_EQ(log[0].cause, devices::TransitionCause::ControlWord);
  EXPECT_EQ(log[0].value, 0x0009u);
}

TEST_F(Recorded, FaultHoldIsTr9AndResetWithHoldIsTr11) {
  dsm.set_fault_hold(true);
  dsm.write_control_word(0x0003);
  log.clear();
  dsm.forced_fault(false, {devices::TransitionCause::NmtCommand, 0x02, "the master"});
  ASSERT_EQ(names(), (Names{"TR_8", "TR_9"}));
  EXPECT_EQ(log[0].cause, devices::TransitionCause::NmtCommand);
  log.clear();
  dsm.write_control_word(0x000B);  // R edge, H = 1
  EXPECT_EQ(names(), (Names{"TR_11"}));
}

TEST_F(Recorded, PowerOffIsRecordedAsOffAndTheNextPowerOnStartsFromOff) {
  dsm.write_control_word(0x0007);
  log.clear();
  dsm.power_off();
  EXPECT_TRUE(dsm.off());
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0].from, "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(log[0].to, "OFF");
  EXPECT_EQ(log[0].cause, devices::TransitionCause::Power);
  log.clear();
  dsm.power_on({devices::TransitionCause::Power, 1, {}});
  EXPECT_EQ(names(), (Names{"TR_0", "TR_1"}));
  EXPECT_EQ(log[0].from, "OFF");
  EXPECT_FALSE(dsm.off());
}
