// devices/state_machine_diagram.h: every edge joins states of its machine, the DSP 408 machine
// has every transition of the manuals' table, and the evidence texts the API serves.
#include "devices/state_machine_diagram.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using devices::Transition;
using devices::TransitionCause;

void expect_edges_join_states(const devices::MachineDiagram& d) {
  for (const auto& e : d.edges) {
    const auto has = [&](std::string_view name) {
      return std::any_of(d.states.begin(), d.states.end(), [&](const auto& s) { return s.name == name; });
    };
    EXPECT_TRUE(has(e.from)) << d.machine << " " << e.transition << " from " << e.from;
    EXPECT_TRUE(has(e.to)) << d.machine << " " << e.transition << " to " << e.to;
    EXPECT_FALSE(e.condition.empty());
  }
}

TEST(StateMachineDiagram, EdgesJoinStatesOfTheirMachine) {
  expect_edges_join_states(devices::nmt_diagram());
  expect_edges_join_states(devices::dsp408_diagram("dsp408.ch3"));
  expect_edges_join_states(devices::vtvpcd_diagram());
  EXPECT_EQ(devices::dsp408_diagram("dsp408.ch3").machine, "dsp408.ch3");
}

TEST(StateMachineDiagram, Dsp408HasEveryTransitionOfTheManual) {
  const auto d = devices::dsp408_diagram("dsp408");
  for (std::string_view tr : {"TR_0", "TR_1", "TR_2", "TR_3", "TR_4", "TR_5", "TR_6", "TR_7", "TR_8", "TR_9", "TR_10", "TR_11", "TR_12", "TR_567"})
    EXPECT_TRUE(std::any_of(d.edges.begin(), d.edges.end(), [&](const auto& e) { return e.transition == tr; })) << tr;
}

TEST(StateMachineDiagram, EvidenceInWords) {
  Transition t;
  t.cause = TransitionCause::ControlWord;
  t.value = 0x000F;
  t.detail = "RPDO";
  EXPECT_EQ(devices::transition_evidence(t), "control word 0x000F (D=1 H=1 M=1 R=1) by RPDO");
  t = {};
  t.cause = TransitionCause::NmtCommand;
  t.value = 0x82;
  t.detail = "the master";
  EXPECT_EQ(devices::transition_evidence(t), "NMT Reset Communication (82h) from the master");
  t = {};
  t.cause = TransitionCause::HeartbeatTimeout;
  t.value = 5;
  EXPECT_EQ(devices::transition_evidence(t), "heartbeat of node 5 missed (1016h consumer)");
  t = {};
  t.cause = TransitionCause::GuardingTimeout;
  t.value = 300;
  EXPECT_EQ(devices::transition_evidence(t), "life guarding: no guard request within 300 ms (100Ch × 100Dh)");
  t = {};
  t.cause = TransitionCause::DeviceFault;
  t.value = 0x5236;
  t.detail = "lvdt_fault";
  EXPECT_EQ(devices::transition_evidence(t), "device fault lvdt_fault (EMCY 5236h)");
  t = {};
  t.cause = TransitionCause::Input;
  t.value = 0;
  t.detail = "enable input";
  EXPECT_EQ(devices::transition_evidence(t), "enable input = 0");
  t = {};
  t.cause = TransitionCause::Power;
  t.to = "OFF";
  EXPECT_EQ(devices::transition_evidence(t), "power switched off");
}

TEST(StateMachineDiagram, SetBitNames) {
  static constexpr devices::DiagramBit kBits[] = {{0, "position error"}, {12, "EEPROM error"}};
  devices::MachineDiagram d{"cia406.alarms", "Alarms", {}, {}, "", 0x6503, kBits, "fault"};
  EXPECT_EQ(devices::set_bit_names(d, 0), "none");
  EXPECT_EQ(devices::set_bit_names(d, 0x1001), "position error + EEPROM error");
  EXPECT_EQ(devices::set_bit_names(d, 0x0002), "none");  // an unnamed bit
}

}  // namespace
