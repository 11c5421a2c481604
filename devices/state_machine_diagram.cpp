#include "devices/state_machine_diagram.h"

#include <array>
#include <cstdio>

namespace devices {

namespace {

// CiA 301 §7.3.2 with the transitions the MD2/DSV manuals number C1–C16 (their figure is lost,
// so the edges carry the command that drives them; the condition names the C numbers).
constexpr std::array kNmtStates = {
    DiagramState{"OFF", "off", 0, 0},
    DiagramState{"INITIALISING", "init", 0, 1},
    DiagramState{"PRE-OPERATIONAL", "normal", 1, 1},
    DiagramState{"OPERATIONAL", "normal", 2, 0},
    DiagramState{"STOPPED", "normal", 2, 2},
};
constexpr std::array kNmtEdges = {
    DiagramEdge{"power on", "OFF", "INITIALISING", "supply switched on (C1)"},
    DiagramEdge{"boot-up", "INITIALISING", "PRE-OPERATIONAL", "initialisation finished, boot-up message 700h+ID sent (C2, C15, C16)"},
    DiagramEdge{"NMT 01h", "PRE-OPERATIONAL", "OPERATIONAL", "Start Remote Node from the master (C3)"},
    DiagramEdge{"NMT 01h", "STOPPED", "OPERATIONAL", "Start Remote Node from the master (C6)"},
    DiagramEdge{"NMT 80h", "OPERATIONAL", "PRE-OPERATIONAL", "Enter Pre-Operational from the master (C4)"},
    DiagramEdge{"NMT 80h", "STOPPED", "PRE-OPERATIONAL", "Enter Pre-Operational from the master (C7)"},
    DiagramEdge{"NMT 02h", "PRE-OPERATIONAL", "STOPPED", "Stop Remote Node from the master (C5)"},
    DiagramEdge{"NMT 02h", "OPERATIONAL", "STOPPED", "Stop Remote Node from the master (C8)"},
    DiagramEdge{"NMT 81h", "OPERATIONAL", "INITIALISING", "Reset Node: application and communication reset (C9)"},
    DiagramEdge{"NMT 81h", "PRE-OPERATIONAL", "INITIALISING", "Reset Node (C10)"},
    DiagramEdge{"NMT 81h", "STOPPED", "INITIALISING", "Reset Node (C11)"},
    DiagramEdge{"NMT 82h", "OPERATIONAL", "INITIALISING", "Reset Communication: 1000h-1FFFh reloaded (C12)"},
    DiagramEdge{"NMT 82h", "PRE-OPERATIONAL", "INITIALISING", "Reset Communication (C13)"},
    DiagramEdge{"NMT 82h", "STOPPED", "INITIALISING", "Reset Communication (C14)"},
    DiagramEdge{"autostart", "PRE-OPERATIONAL", "OPERATIONAL", "the product starts itself after the boot-up (HLT 1100 autostart setting)"},
    DiagramEdge{"1F80h", "PRE-OPERATIONAL", "OPERATIONAL", "NMT start-up 1F80h = 02h/08h: the node starts itself after the boot-up (WDGA)"},
    DiagramEdge{"1029h:01", "OPERATIONAL", "PRE-OPERATIONAL",
                "communication error (heartbeat consumer or life guarding timeout, bus-off recovered) with error behaviour 1029h:01 = 0"},
    DiagramEdge{"1029h:01", "OPERATIONAL", "STOPPED", "communication error with error behaviour 1029h:01 = 2"},
    DiagramEdge{"1029h:01", "PRE-OPERATIONAL", "STOPPED", "communication error with error behaviour 1029h:01 = 2"},
    DiagramEdge{"1029h:02", "OPERATIONAL", "PRE-OPERATIONAL", "a device error (WDGA position error) with error behaviour 1029h:02 = 0"},
    DiagramEdge{"1029h:02", "OPERATIONAL", "STOPPED", "a device error with error behaviour 1029h:02 = 2"},
    DiagramEdge{"power off", "INITIALISING", "OFF", "supply switched off"},
    DiagramEdge{"power off", "PRE-OPERATIONAL", "OFF", "supply switched off"},
    DiagramEdge{"power off", "OPERATIONAL", "OFF", "supply switched off"},
    DiagramEdge{"power off", "STOPPED", "OFF", "supply switched off"},
};
constexpr MachineDiagram kNmt{
    "nmt", "NMT (CiA 301)", kNmtStates, kNmtEdges,
    "A node answers SDO in PRE-OPERATIONAL and OPERATIONAL and sends PDOs only in OPERATIONAL. A product may "
    "start itself (a start-up setting: PRE-OPERATIONAL → OPERATIONAL without a command); 1029h:01 is the error "
    "behaviour, the node's own reaction to a communication error, not an NMT command.",
    0, {}, "normal"};

// MD2/DSV manuals §5.2.2 (control word bits: D = bit 0, H = bit 1, M = bit 2, R = bit 3).
constexpr std::array kDspStates = {
    DiagramState{"OFF", "off", 0, 0},
    DiagramState{"NOT_READY", "init", 0, 1},
    DiagramState{"INIT", "init", 1, 1},
    DiagramState{"DISABLED", "normal", 2, 1},
    DiagramState{"HOLD", "normal", 3, 1},
    DiagramState{"DEVICE_MODE_ACTIVE", "normal", 4, 1},
    DiagramState{"FAULT_REACTION", "fault", 2, 3},
    DiagramState{"FAULT", "fault", 3, 3},
    DiagramState{"FAULT_HOLD", "fault", 4, 3},
};
constexpr std::array kDspEdges = {
    DiagramEdge{"TR_0", "OFF", "NOT_READY", "supply voltage switched on; self test"},
    DiagramEdge{"TR_1", "NOT_READY", "INIT", "device initialisation completed"},
    DiagramEdge{"TR_2", "INIT", "DISABLED", "control word bit D (Disable) = 1 (bus operation: with the enable input at 1)"},
    DiagramEdge{"TR_3", "DISABLED", "HOLD", "control word bits D = 1, H (Hold enable) = 1"},
    DiagramEdge{"TR_4", "HOLD", "DEVICE_MODE_ACTIVE", "control word bits D = H = M (Device mode active enable) = 1, a control mode selected"},
    DiagramEdge{"TR_5", "DEVICE_MODE_ACTIVE", "HOLD", "control word bit M = 0"},
    DiagramEdge{"TR_6", "HOLD", "DISABLED", "control word bits M = 0, H = 0"},
    DiagramEdge{"TR_7", "DISABLED", "INIT", "control word bits M = H = D = 0"},
    DiagramEdge{"TR_567", "DEVICE_MODE_ACTIVE", "INIT", "forced: NMT Reset Node (C9-C11) or the enable input 1 → 0"},
    DiagramEdge{"TR_567", "HOLD", "INIT", "forced: NMT Reset Node or the enable input 1 → 0"},
    DiagramEdge{"TR_567", "DISABLED", "INIT", "forced: NMT Reset Node or the enable input 1 → 0"},
    DiagramEdge{"TR_8", "INIT", "FAULT_REACTION", "an error (EMCY), or forced by NMT Stop (C5, C8) / Reset Communication (C12-C14) / life guarding"},
    DiagramEdge{"TR_8", "DISABLED", "FAULT_REACTION", "an error, or forced by the communication state machine"},
    DiagramEdge{"TR_8", "HOLD", "FAULT_REACTION", "an error, or forced by the communication state machine"},
    DiagramEdge{"TR_8", "DEVICE_MODE_ACTIVE", "FAULT_REACTION", "an error, or forced by the communication state machine"},
    DiagramEdge{"TR_12", "FAULT_REACTION", "FAULT", "error reaction done (functions disabled)"},
    DiagramEdge{"TR_9", "FAULT_REACTION", "FAULT_HOLD", "error reaction done with HOLD active (option fault_hold)"},
    DiagramEdge{"TR_10", "FAULT", "DISABLED", "control word bit R (Reset fault) 0 → 1 with H = 0, no error present any more"},
    DiagramEdge{"TR_11", "FAULT_HOLD", "HOLD", "control word bit R 0 → 1 with H = 1, no error present any more"},
};
constexpr std::string_view kDspNote =
    "One control word write runs every transition it enables, each recorded on its own: 0x0007 in INIT is "
    "TR_2, TR_3, TR_4; 0x0000 in DEVICE_MODE_ACTIVE is TR_5, TR_6, TR_7. TR_567 is only the forced path (NMT "
    "Reset Node, the enable input). Under local operation (604Fh = 1) the enable input drives the machine.";

// VT-VPCD (manual §3.1 "internal operational states ... fault states, waiting for enable"; the
// digest's §4.9 for the latch).
constexpr std::array kVtStates = {
    DiagramState{"OFF", "off", 0, 0},
    DiagramState{"INITIALISING", "init", 0, 1},
    DiagramState{"NOT_ENABLED", "normal", 1, 1},
    DiagramState{"RUNNING", "normal", 2, 1},
    DiagramState{"FAULT_STOP", "fault", 2, 2},
};
constexpr std::array kVtEdges = {
    DiagramEdge{"power on", "OFF", "INITIALISING", "supply switched on: the card loads its configuration image"},
    DiagramEdge{"boot-up", "INITIALISING", "RUNNING", "initialisation finished (boot-up message), Enable input = 1"},
    DiagramEdge{"boot-up", "INITIALISING", "NOT_ENABLED", "initialisation finished, Enable input = 0"},
    DiagramEdge{"enable", "NOT_ENABLED", "RUNNING", "Enable input 0 → 1: the controller energises the pilot valve"},
    DiagramEdge{"disable", "RUNNING", "NOT_ENABLED", "Enable input 1 → 0: valve de-energised, the pump swivels to its fail position"},
    DiagramEdge{"stop fault", "RUNNING", "FAULT_STOP", "a stop fault appears (EMCY): valve de-energised, OK output off"},
    DiagramEdge{"stop fault", "NOT_ENABLED", "FAULT_STOP", "a stop fault appears (EMCY)"},
    DiagramEdge{"acknowledge", "FAULT_STOP", "RUNNING",
                "Enable input edge 1 → 0 → 1 once the fault's cause is gone (the latch is acknowledged on the rising edge)"},
    DiagramEdge{"acknowledge", "FAULT_STOP", "NOT_ENABLED", "the cause is gone with Enable = 0 (option fault_latch = false)"},
    DiagramEdge{"NMT 81h", "RUNNING", "INITIALISING", "Reset of amplifier card: everything reloaded, faults re-evaluated"},
    DiagramEdge{"NMT 81h", "NOT_ENABLED", "INITIALISING", "Reset of amplifier card"},
    DiagramEdge{"NMT 81h", "FAULT_STOP", "INITIALISING", "Reset of amplifier card: the latch is cleared"},
    DiagramEdge{"power off", "RUNNING", "OFF", "supply switched off"},
};
constexpr MachineDiagram kVtvpcd{
    "vtvpcd", "VT-VPCD pump control", kVtStates, kVtEdges,
    "A stop fault stays latched after its cause has gone: acknowledge it with an Enable input edge 1 → 0 → 1 "
    "(or NMT 81h Reset of amplifier card). Writes over the bus take effect in any state (\"value acceptance "
    "also with active enabling\").",
    0, {}, "normal"};

std::string hex(std::uint32_t v, int digits) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%0*X", digits, v);
  return buf;
}

std::string_view nmt_command_name(std::uint32_t cs) {
  switch (cs) {
    case 0x01: return "Start Remote Node";
    case 0x02: return "Stop Remote Node";
    case 0x80: return "Enter Pre-Operational";
    case 0x81: return "Reset Node";
    case 0x82: return "Reset Communication";
    default: return "command";
  }
}

}  // namespace

const MachineDiagram& nmt_diagram() { return kNmt; }

MachineDiagram dsp408_diagram(std::string_view machine) {
  MachineDiagram d{machine, "Device state machine (CiA DSP 408)", kDspStates, kDspEdges, kDspNote, 0, {}, "normal"};
  if (machine.size() > 6) d.title = "Device state machine (CiA DSP 408), channel";
  return d;
}

const MachineDiagram& vtvpcd_diagram() { return kVtvpcd; }

std::string transition_evidence(const Transition& t) {
  const std::string detail(t.detail);
  switch (t.cause) {
    case TransitionCause::Boot: return "power-on (boot)";
    case TransitionCause::Power: return t.to == "OFF" ? "power switched off" : "power switched on";
    case TransitionCause::ControlWord: {
      const auto bit = [&](int n) { return (t.value >> n) & 1u ? '1' : '0'; };
      std::string s = "control word 0x" + hex(t.value, 4) + " (D=" + bit(0) + " H=" + bit(1) + " M=" + bit(2) + " R=" + bit(3) + ")";
      if (!detail.empty()) s += " by " + detail;
      return s;
    }
    case TransitionCause::NmtCommand: {
      std::string s = "NMT " + std::string(nmt_command_name(t.value)) + " (" + hex(t.value, 2) + "h)";
      s += " from " + (detail.empty() ? std::string("the master") : detail);
      return s;
    }
    case TransitionCause::Input:
      return (detail.empty() ? std::string("input") : detail) + " = " + std::to_string(t.value);
    case TransitionCause::HeartbeatTimeout:
      return "heartbeat of node " + std::to_string(t.value) + " missed (1016h consumer)";
    case TransitionCause::GuardingTimeout:
      return "life guarding: no guard request within " + std::to_string(t.value) + " ms (100Ch × 100Dh)";
    case TransitionCause::BusOff: return detail == "recovered" ? "CAN controller recovered from bus-off" : "CAN controller bus-off";
    case TransitionCause::Reset: return "application reset" + (detail.empty() ? std::string() : " (" + detail + ")");
    case TransitionCause::DeviceFault: {
      std::string s = "device fault";
      if (!detail.empty()) s += " " + detail;
      if (t.value != 0) s += " (EMCY " + hex(t.value, 4) + "h)";
      return s;
    }
    case TransitionCause::Internal: break;
  }
  // A status word's change (CiA 406 bits) shows the word's new value, 0 included.
  if (t.machine.starts_with("cia406.")) return detail + " = 0x" + hex(t.value, 4);
  if (!detail.empty()) return detail + (t.value != 0 ? " = 0x" + hex(t.value, 4) : std::string());
  return "the device's own sequence";
}

std::string set_bit_names(const MachineDiagram& d, std::uint16_t word) {
  std::string s;
  for (const auto& b : d.bits) {
    if (!((word >> b.bit) & 1u)) continue;
    if (!s.empty()) s += " + ";
    s += b.name;
  }
  return s.empty() ? "none" : s;
}

}  // namespace devices
