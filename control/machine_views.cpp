#include "control/machine_views.h"

#include <cstdio>

namespace control {

using nlohmann::json;

json transition_json(const devices::Transition& t) {
  return {{"seq", t.seq},
          {"t_us", t.t_us},
          {"machine", std::string(t.machine)},
          {"from", std::string(t.from)},
          {"to", std::string(t.to)},
          {"transition", std::string(t.transition)},
          {"cause", std::string(devices::to_string(t.cause))},
          {"value", t.value},
          {"detail", std::string(t.detail)},
          {"evidence", devices::transition_evidence(t)}};
}

std::vector<devices::Transition> transitions_after(const devices::TransitionLog& log, std::uint64_t after) {
  std::vector<devices::Transition> out;
  out.reserve(log.size());
  log.for_each_after(after, [&out](const devices::Transition& t) { out.push_back(t); });
  return out;
}

namespace {

json machine_json(const devices::MachineView& m) {
  const auto& d = m.diagram;
  json states = json::array(), edges = json::array();
  for (const auto& s : d.states)
    states.push_back({{"name", std::string(s.name)}, {"kind", std::string(s.kind)}, {"row", s.row}, {"col", s.col}});
  for (const auto& e : d.edges)
    edges.push_back({{"transition", std::string(e.transition)},
                     {"from", std::string(e.from)},
                     {"to", std::string(e.to)},
                     {"condition", std::string(e.condition)}});
  if (d.word_index != 0) {
    // A bit machine: "none" and one state per named bit (several may be set at once); a bit
    // that sets is the edge none → its name, one that clears the way back (as recorded).
    char object[8];
    std::snprintf(object, sizeof object, "%04Xh", d.word_index);
    states.push_back({{"name", "none"}, {"kind", "normal"}, {"row", 0}, {"col", 0}});
    int k = 0;
    for (const auto& b : d.bits) {
      const std::string name(b.name), where = std::string(object) + " bit " + std::to_string(b.bit);
      states.push_back({{"name", name}, {"kind", std::string(d.bit_kind)}, {"row", 1 + k / 4}, {"col", k % 4}});
      edges.push_back({{"transition", "set"}, {"from", "none"}, {"to", name}, {"condition", where + " set"}});
      edges.push_back({{"transition", "cleared"}, {"from", name}, {"to", "none"}, {"condition", where + " cleared"}});
      ++k;
    }
  }
  json j = {{"machine", std::string(d.machine)}, {"title", std::string(d.title)}, {"state", m.state},
            {"states", states}, {"edges", edges}, {"note", std::string(d.note)}};
  if (d.word_index != 0) {
    json bits = json::array();
    for (const auto& b : d.bits) bits.push_back({{"bit", b.bit}, {"name", std::string(b.name)}});
    j["bits"] = bits;
  }
  return j;
}

}  // namespace

json machines_json(const std::string& node, bool powered, const std::vector<devices::MachineView>& machines) {
  json list = json::array();
  for (const auto& m : machines) list.push_back(machine_json(m));
  return {{"node", node}, {"powered", powered}, {"machines", list}};
}

}  // namespace control
