#include "devices/profiles/cia406/status_machines.h"

#include <array>
#include <string_view>

namespace cia406 {

namespace {

struct Word {
  std::uint16_t index;
  std::string_view machine, title, kind, note;
};
constexpr std::array<Word, 3> kWords = {{
    {0x6500, "cia406.status", "Operating status 6500h (CiA 406)", "normal",
     "Mirrors the operating parameters 6000h in effect; each named bit is shown as a state of its own."},
    {0x6503, "cia406.alarms", "Alarms 6503h (CiA 406)", "fault",
     "An alarm bit is set while its condition lasts (the product sends its EMCY); several may be set at once."},
    {0x6505, "cia406.warnings", "Warnings 6505h (CiA 406)", "fault",
     "A warning bit is set while its condition lasts; warnings do not stop the position output."},
}};

std::span<const devices::DiagramBit> bits_of(const StatusBitNames& n, std::size_t k) {
  return k == 0 ? n.status : k == 1 ? n.alarms : n.warnings;
}

std::uint16_t word(const canopen::ObjectDictionary& od, std::uint16_t index) {
  const auto* e = od.entry(index, 0);
  return e ? e->as<std::uint16_t>() : std::uint16_t{0};
}

}  // namespace

std::vector<devices::MachineDiagram> status_diagrams(const StatusBitNames& names) {
  std::vector<devices::MachineDiagram> out;
  for (std::size_t k = 0; k < kWords.size(); ++k) {
    const auto& w = kWords[k];
    out.push_back(devices::MachineDiagram{w.machine, w.title, {}, {}, w.note, w.index, bits_of(names, k), w.kind});
  }
  return out;
}

void append_status_machines(const canopen::Node& node, const StatusBitNames& names, std::vector<devices::MachineView>& out) {
  for (const auto& d : status_diagrams(names))
    out.push_back({d, node.powered() ? devices::set_bit_names(d, word(node.od(), d.word_index)) : "OFF"});
}

void StatusRecorder::raised_by_fault(Word word, std::uint16_t bits, std::uint16_t emcy_code) {
  const auto k = static_cast<std::size_t>(word);
  fault_bits_[k] = static_cast<std::uint16_t>(fault_bits_[k] | bits);
  for (unsigned bit = 0; bit < 16; ++bit)
    if ((bits >> bit) & 1u) fault_code_[k][bit] = emcy_code;
}

void StatusRecorder::check() {
  if (!bound_) {  // the dictionary's entries stay where they are: looked up once, not per tick
    for (std::size_t k = 0; k < kWords.size(); ++k) entries_[k] = node_.od().entry(kWords[k].index, 0);
    bound_ = true;
  }
  for (std::size_t k = 0; k < kWords.size(); ++k) {
    const std::uint16_t now = entries_[k] ? entries_[k]->as<std::uint16_t>() : std::uint16_t{0};
    const std::uint16_t changed = now ^ last_[k];
    const std::uint16_t by_fault = fault_bits_[k];
    fault_bits_[k] = 0;  // a note is for the change it announced, not a later one
    if (changed == 0) continue;
    last_[k] = now;
    auto* log = node_.transition_log();
    if (!log) continue;
    const auto t_us = static_cast<std::uint64_t>(node_.now().time_since_epoch().count());
    for (const auto& b : bits_of(names_, k)) {
      if (!((changed >> b.bit) & 1u)) continue;
      const bool set = (now >> b.bit) & 1u;
      const std::string_view from = set ? std::string_view("none") : b.name, to = set ? b.name : std::string_view("none");
      if (set && ((by_fault >> b.bit) & 1u)) {  // the fault with its EMCY code, as DSP 408 names it
        log->record({0, t_us, kWords[k].machine, from, to, "set", devices::TransitionCause::DeviceFault,
                     fault_code_[k][b.bit], b.name});
        continue;
      }
      // Otherwise the object's new value is the evidence; detail names the object (static text).
      log->record({0, t_us, kWords[k].machine, from, to, set ? "set" : "cleared", devices::TransitionCause::Internal, now,
                   kWords[k].title});
    }
  }
}

}  // namespace cia406
