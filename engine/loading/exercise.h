// Exercises as files (docs/exercises.md): a title, an introduction and steps a trainee does in
// order, each with an instruction, an optional hint and a goal the plant checks live. A goal is
// written in the scenario language: a condition on a signal (`signal: dsv.nmt_state, value: 5`),
// a frame pattern seen on a bus (`frame: {id: 0x702, data: "05"}`) or a device transition from
// the devices' own transition logs (`transition: {node: dsv, to: DEVICE_MODE_ACTIVE}`). Read by
// the scenario's strict reader: every error is a LoadError `file:line:col: reason`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "engine/loading/condition.h"
#include "engine/loading/frame_pattern.h"
#include "engine/loading/source_mark.h"

namespace scenario {

/// A state change a device's transition log must show (devices/transition_log.h); empty fields
/// match anything.
struct TransitionGoal {
  std::string node;
  std::string machine;     ///< "nmt", "dsp408", "dsp408.ch2", "vtvpcd", "cia406.status", …
  std::string from, to;    ///< state names as the manuals spell them
  std::string transition;  ///< "TR_5", …
};

struct ExerciseGoal {
  enum class Kind { Condition, Frame, Transition } kind = Kind::Condition;
  Condition condition;
  FramePattern frame;
  std::string bus;  ///< Frame: "" = the scenario's first bus
  TransitionGoal transition;
  SourceMark mark;
  std::string summary;  ///< "dsv.nmt_state = 5 ± 0", "frame 0x702 05", "dsv dsp408 → DEVICE_MODE_ACTIVE"
};

struct ExerciseStep {
  std::string title;
  std::string text;
  std::string hint;  ///< "" = none
  ExerciseGoal goal;
  SourceMark mark;
};

struct Exercise {
  std::string name;  ///< the file's name without `.yaml`
  std::string file;
  std::string title;
  std::string introduction;
  std::vector<ExerciseStep> steps;
};

/// Bounds: a client may select any file of the folder, so each is limited.
inline constexpr std::size_t kMaxExerciseSteps = 64;
inline constexpr std::size_t kMaxExerciseFileBytes = 256u << 10;
inline constexpr std::size_t kMaxExercisesListed = 256;

/// Parses an exercise; throws LoadError.
Exercise parse_exercise(const std::string& text, const std::string& file, const std::string& name);
/// Reads `dir`/`name`.yaml; throws LoadError (an unknown or malformed name included).
Exercise load_exercise(const std::string& dir, const std::string& name);
/// The exercise names in `dir` (files `*.yaml` with a valid name), sorted; at most
/// kMaxExercisesListed. Empty when the folder cannot be read.
std::vector<std::string> list_exercises(const std::string& dir);
/// A name an exercise file may have: letters, digits, '_' and '-' (no path), 1..64 characters.
bool valid_exercise_name(const std::string& name);

}  // namespace scenario
