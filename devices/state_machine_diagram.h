// What a device's state machines look like, for a page to draw without knowing them: states with
// a kind and a row/column layout hint, edges named as the manuals name them (TR_n, NMT 01h) with
// their conditions in words, and a note. The same names as the transition log (transition_log.h),
// so a recorded transition lights up its edge. Static data: the C++ profiles are the only place
// the machines are written down.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "devices/transition_log.h"

namespace devices {

struct DiagramState {
  std::string_view name;
  std::string_view kind;  ///< "normal", "fault", "off", "init"
  int row = 0, col = 0;
};

struct DiagramEdge {
  std::string_view transition, from, to, condition;
};

/// A bit of a status word shown as a state of its own (CiA 406 alarms): set or not.
struct DiagramBit {
  int bit = 0;
  std::string_view name;
};

struct MachineDiagram {
  std::string_view machine, title;
  std::span<const DiagramState> states;
  std::span<const DiagramEdge> edges;
  std::string_view note;
  /// Bit machines only: the word's object (0x6503) and its named bits; the state then lists the
  /// set bits ("none" when no bit is set).
  std::uint16_t word_index = 0;
  std::span<const DiagramBit> bits;
  std::string_view bit_kind = "normal";  ///< the kind of a set bit's state ("fault" for alarms)
};

/// One of a device's state machines as the page draws it, with the state it is in now.
struct MachineView {
  MachineDiagram diagram;
  std::string state;  ///< a state of the diagram ("OFF" while unpowered); bit machines: the set bits
};

/// CiA 301 NMT (every node) with OFF for an unpowered node.
const MachineDiagram& nmt_diagram();
/// CiA DSP 408 device state machine as the DSV/MD2 manuals (§5.2.2) describe it; `machine` is
/// "dsp408" or "dsp408.ch1" … "dsp408.ch8" (static text).
MachineDiagram dsp408_diagram(std::string_view machine);
/// The VT-VPCD's run states (enable input, stop faults latched until an enable edge).
const MachineDiagram& vtvpcd_diagram();

/// The cause of a transition in words, with its evidence ("control word 0x0000 (D=0 H=0 M=0
/// R=0) by SDO", "NMT Stop (02h) from the master", "heartbeat of node 5 missed (1016h)").
std::string transition_evidence(const Transition& t);

/// The names of the bits set in `word` ("none" when no named bit is set), joined by " + ".
std::string set_bit_names(const MachineDiagram& d, std::uint16_t word);

}  // namespace devices
