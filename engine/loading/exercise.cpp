#include "engine/loading/exercise.h"

#include <dirent.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "engine/loading/scenario_loader.h"
#include "engine/loading/script_loader.h"
#include "engine/loading/yaml_fields.h"
#include "sim/file_reader.h"

namespace scenario {

namespace {

// The state names the transition logs use (devices/transition_log.h): a goal naming another state
// of these machines could never be met, so it is refused when the file is read.
constexpr std::array<std::string_view, 5> kNmtStates = {"INITIALISING", "PRE-OPERATIONAL", "OPERATIONAL", "STOPPED", "OFF"};
constexpr std::array<std::string_view, 9> kDsp408States = {"NOT_READY", "INIT",         "DISABLED",
                                                           "HOLD",      "DEVICE_MODE_ACTIVE", "FAULT_REACTION",
                                                           "FAULT",     "FAULT_HOLD",   "OFF"};

bool dsp408_machine(std::string_view m) {
  if (m == "dsp408") return true;
  if (m.size() != 10 || m.substr(0, 9) != "dsp408.ch") return false;
  return m[9] >= '1' && m[9] <= '8';
}

bool known_machine(std::string_view m) {
  return m == "nmt" || dsp408_machine(m) || m == "vtvpcd" || m == "cia406.status" || m == "cia406.alarms" ||
         m == "cia406.warnings";
}

template <std::size_t N>
bool contains(const std::array<std::string_view, N>& names, std::string_view s) {
  return std::find(names.begin(), names.end(), s) != names.end();
}

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& names) {
  std::string out;
  for (const auto n : names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

/// A state name of `machine` (any machine when it is ""): checked against the known vocabulary.
std::string read_state(const YAML::Node& n, const std::string& file, const char* what, const std::string& machine) {
  const auto s = read_string(n, file, what);
  if (s.empty()) throw LoadError(mark_of(n, file), std::string(what) + ": empty state name");
  if (machine == "nmt" && !contains(kNmtStates, s))
    throw LoadError(mark_of(n, file), std::string(what) + ": '" + s + "' is not an NMT state (" + joined(kNmtStates) + ")");
  if (dsp408_machine(machine) && !contains(kDsp408States, s))
    throw LoadError(mark_of(n, file),
                    std::string(what) + ": '" + s + "' is not a DSP 408 state (" + joined(kDsp408States) + ")");
  return s;
}

TransitionGoal read_transition(const YAML::Node& n, const std::string& file) {
  MapReader r(n, file, "transition");
  TransitionGoal t;
  t.node = read_name(r.require("node"), file, "node");
  if (auto m = r.get("machine")) {
    t.machine = read_string(m, file, "machine");
    if (!known_machine(t.machine))
      throw LoadError(mark_of(m, file), "machine: '" + t.machine +
                                            "' is not a state machine (nmt, dsp408, dsp408.ch1 … dsp408.ch8, vtvpcd, "
                                            "cia406.status, cia406.alarms, cia406.warnings)");
  }
  if (auto f = r.get("from")) t.from = read_state(f, file, "from", t.machine);
  if (auto to = r.get("to")) t.to = read_state(to, file, "to", t.machine);
  if (auto tr = r.get("transition")) t.transition = read_string(tr, file, "transition");
  r.finish();
  if (t.to.empty() && t.transition.empty())
    throw LoadError(r.mark(), "transition: give 'to' (the state reached) or 'transition' (its name, e.g. TR_5)");
  return t;
}

std::string describe(const TransitionGoal& t) {
  std::string s = t.node;
  if (!t.machine.empty()) s += " " + t.machine;
  if (!t.transition.empty()) s += " " + t.transition;
  if (!t.from.empty()) s += " " + t.from;
  if (!t.to.empty()) s += " → " + t.to;
  return s;
}

ExerciseGoal read_goal(const YAML::Node& n, const std::string& file) {
  MapReader r(n, file, "goal");
  ExerciseGoal g;
  g.mark = r.mark();
  const auto kind = r.one_of({"signal", "frame", "transition"});
  if (kind == "signal") {
    g.kind = ExerciseGoal::Kind::Condition;
    g.condition = read_condition(r, file);
    g.summary = g.condition.describe();
  } else if (kind == "frame") {
    g.kind = ExerciseGoal::Kind::Frame;
    MapReader fr(r.get("frame"), file, "frame");
    g.frame = read_pattern(fr, file, "data");
    if (auto b = fr.get("bus")) g.bus = read_name(b, file, "bus");
    fr.finish();
    g.summary = "frame " + g.frame.describe() + (g.bus.empty() ? "" : " on " + g.bus);
  } else {
    g.kind = ExerciseGoal::Kind::Transition;
    g.transition = read_transition(r.get("transition"), file);
    g.summary = describe(g.transition);
  }
  r.finish();
  return g;
}

ExerciseStep read_step(const YAML::Node& n, const std::string& file) {
  MapReader r(n, file, "step");
  ExerciseStep s;
  s.mark = r.mark();
  s.title = read_string(r.require("title"), file, "title");
  s.text = read_string(r.require("text"), file, "text");
  if (auto h = r.get("hint")) s.hint = read_string(h, file, "hint");
  s.goal = read_goal(r.require("goal"), file);
  r.finish();
  return s;
}

}  // namespace

bool valid_exercise_name(const std::string& name) {
  return !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
           return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
         });
}

Exercise parse_exercise(const std::string& text, const std::string& file, const std::string& name) {
  const auto root = parse_yaml(text, file);
  if (!root.IsDefined() || root.IsNull()) throw LoadError(SourceMark{file, 1, 1}, "empty exercise file");
  MapReader r(root, file, "exercise");
  Exercise e;
  e.name = name;
  e.file = file;
  e.title = read_string(r.require("title"), file, "title");
  e.introduction = read_string(r.require("introduction"), file, "introduction");
  const auto steps = r.require("steps");
  if (!steps.IsSequence() || steps.size() == 0) throw LoadError(mark_of(steps, file), "steps: expected a list of steps");
  if (steps.size() > kMaxExerciseSteps)
    throw LoadError(mark_of(steps, file), "steps: at most " + std::to_string(kMaxExerciseSteps) + " steps");
  for (const auto& s : steps) e.steps.push_back(read_step(s, file));
  r.finish();
  return e;
}

Exercise load_exercise(const std::string& dir, const std::string& name) {
  if (!valid_exercise_name(name))
    throw LoadError(SourceMark{name, 0, 0}, "not an exercise name (letters, digits, '_', '-', at most 64)");
  const std::string path = dir + "/" + name + ".yaml";
  std::string text, reason;
  switch (sim::read_input_file(path, text, reason, kMaxExerciseFileBytes)) {
    case sim::ReadStatus::Ok: break;
    case sim::ReadStatus::Missing: throw LoadError(SourceMark{path, 0, 0}, "no exercise '" + name + "' in " + dir);
    case sim::ReadStatus::Failed: throw LoadError(SourceMark{path, 0, 0}, reason);
  }
  return parse_exercise(text, path, name);
}

std::vector<std::string> list_exercises(const std::string& dir) {
  std::vector<std::string> names;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return names;
  while (const dirent* entry = ::readdir(d)) {
    const std::string f = entry->d_name;
    constexpr std::string_view kExt = ".yaml";
    if (f.size() <= kExt.size() || f.compare(f.size() - kExt.size(), kExt.size(), kExt) != 0) continue;
    const auto name = f.substr(0, f.size() - kExt.size());
    if (valid_exercise_name(name)) names.push_back(name);
  }
  ::closedir(d);
  std::sort(names.begin(), names.end());
  if (names.size() > kMaxExercisesListed) names.resize(kMaxExercisesListed);
  return names;
}

}  // namespace scenario
