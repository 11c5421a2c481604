// Exercise files (engine/loading/exercise.*): the strict reader's errors with their positions, the shipped
// exercises, and the goal checker's order, done times and chains, on its own signals and logs.
#include "engine/loading/exercise.h"

#include <gtest/gtest.h>

#include "engine/running/exercise_checker.h"

namespace {

using scenario::Exercise;
using scenario::ExerciseChecker;
using scenario::LoadError;

std::string error_of(const std::string& text) {
  try {
    scenario::parse_exercise(text, "x.yaml", "x");
  } catch (const LoadError& e) {
    return e.what();
  }
  return "";
}

const char* const kHead = "title: T\nintroduction: I\nsteps:\n";

TEST(ExerciseFile, ReadsStepsAndGoals) {
  const auto e = scenario::parse_exercise(std::string(kHead) +
                                              "  - {title: a, text: ta, hint: ha, goal: {signal: dsv.nmt_state, value: 5, tolerance: 0}}\n"
                                              "  - {title: b, text: tb, goal: {frame: {id: 0x702, data: \"00\"}}}\n"
                                              "  - {title: c, text: tc, goal: {transition: {node: dsv, machine: dsp408, from: HOLD, to: DEVICE_MODE_ACTIVE, transition: TR_4}}}\n",
                                          "x.yaml", "x");
  EXPECT_EQ(e.title, "T");
  EXPECT_EQ(e.introduction, "I");
  ASSERT_EQ(e.steps.size(), 3u);
  EXPECT_EQ(e.steps[0].hint, "ha");
  EXPECT_EQ(e.steps[0].goal.kind, scenario::ExerciseGoal::Kind::Condition);
  EXPECT_EQ(e.steps[0].goal.summary, "dsv.nmt_state = 5 ± 0");
  EXPECT_EQ(e.steps[1].goal.kind, scenario::ExerciseGoal::Kind::Frame);
  EXPECT_EQ(e.steps[1].goal.frame.id, 0x702u);
  EXPECT_EQ(e.steps[2].goal.transition.to, "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(e.steps[2].goal.summary, "dsv dsp408 TR_4 HOLD → DEVICE_MODE_ACTIVE");
}

TEST(ExerciseFile, RejectsWithFileLineColumn) {
  EXPECT_EQ(error_of("title: T\n"), "x.yaml:1:1: exercise: missing key 'introduction'");
  EXPECT_EQ(error_of(std::string(kHead) + "  - {title: a, text: b, goal: {signal: dsv.nmt_state, value: 5, tolerance: 0}, hnit: c}\n"),
            "x.yaml:4:80: unknown key 'hnit' in step (known: title, text, hint, goal)");
  EXPECT_EQ(error_of(std::string(kHead) + "  - {title: a, text: b, goal: {transition: {node: dsv, machine: dsp408, to: ACTIVE}}}\n"),
            "x.yaml:4:77: to: 'ACTIVE' is not a DSP 408 state (NOT_READY, INIT, DISABLED, HOLD, DEVICE_MODE_ACTIVE, "
            "FAULT_REACTION, FAULT, FAULT_HOLD, OFF)");
  EXPECT_EQ(error_of(std::string(kHead) + "  - {title: a, text: b, goal: {transition: {node: dsv, machine: dsp409, to: INIT}}}\n"),
            "x.yaml:4:65: machine: 'dsp409' is not a state machine (nmt, dsp408, dsp408.ch1 … dsp408.ch8, vtvpcd, "
            "cia406.status, cia406.alarms, cia406.warnings)");
  EXPECT_EQ(error_of(std::string(kHead) + "  - {title: a, text: b, goal: {transition: {node: dsv}}}\n"),
            "x.yaml:4:44: transition: give 'to' (the state reached) or 'transition' (its name, e.g. TR_5)");
  EXPECT_EQ(error_of(std::string(kHead) + "  - {title: a, text: b, goal: {signal: dsv.nmt_state, above: 1, frame: {id: 1}}}\n"),
            "x.yaml:4:65: goal: 'signal' and 'frame' cannot be combined");
  EXPECT_EQ(error_of(std::string(kHead) + "  - {title: a, text: b, goal: {frame: {id: 0x702, data: \"0G\"}}}\n").substr(0, 14), "x.yaml:4:57: d");
  EXPECT_EQ(error_of("title: T\nintroduction: I\nsteps: []\n"), "x.yaml:3:8: steps: expected a list of steps");
  EXPECT_EQ(error_of("title: [\n"), "x.yaml:2:1: YAML syntax error: end of sequence flow not found");
}

TEST(ExerciseFile, UnknownOrBadNames) {
  EXPECT_FALSE(scenario::valid_exercise_name("../etc/passwd"));
  EXPECT_FALSE(scenario::valid_exercise_name(""));
  EXPECT_TRUE(scenario::valid_exercise_name("dsp408"));
  EXPECT_THROW(scenario::load_exercise(VPLANT_EXERCISES, "no-such"), LoadError);
  EXPECT_THROW(scenario::load_exercise(VPLANT_EXERCISES, "../README"), LoadError);
  EXPECT_TRUE(scenario::list_exercises("/no/such/folder").empty());
}

TEST(ExerciseFile, ShippedExercisesLoad) {
  const auto names = scenario::list_exercises(VPLANT_EXERCISES);
  for (const char* want : {"nmt", "heartbeat"})
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  for (const auto& n : names) {
    SCOPED_TRACE(n);
    const auto e = scenario::load_exercise(VPLANT_EXERCISES, n);
    EXPECT_FALSE(e.title.empty());
    EXPECT_GE(e.steps.size(), 2u);
  }
}

// ---- the checker, on a double and a log of its own ------------------------------------------

struct Bench {
  double value = 0;
  devices::TransitionLog log;
  scenario::GoalBinding binding() {
    scenario::GoalBinding b;
    b.signal = [this](const scenario::SignalExpr& e) { return scenario::Signal::port(&value, e.scale, e.offset, e.text); };
    b.bus = [](const scenario::ExerciseGoal&) { return 0; };
    b.log = [this](const scenario::ExerciseGoal&) { return &log; };
    return b;
  }
  void record(std::uint64_t t_us, const char* machine, const char* from, const char* to, const char* tr) {
    devices::Transition t;
    t.t_us = t_us;
    t.machine = machine;
    t.from = from;
    t.to = to;
    t.transition = tr;
    log.record(t);
  }
};

Exercise parse(const std::string& steps) { return scenario::parse_exercise(std::string(kHead) + steps, "x.yaml", "x"); }

TEST(ExerciseChecker, StepsCompleteInOrderWithTheirTimes) {
  const auto e = parse("  - {title: a, text: t, goal: {signal: x.v, above: 1}}\n"
                       "  - {title: b, text: t, goal: {frame: {id: 0x702, data: \"00\"}}}\n");
  Bench bench;
  ExerciseChecker c(e, bench.binding());
  // The frame of step 2 before step 1 is done does not count.
  c.on_frame(0, sim::CanFrame::data_frame(0x702, {0x00}), 500);
  c.check(1000);
  EXPECT_EQ(c.current(), 0u);
  bench.value = 2;
  c.check(2000);
  ASSERT_EQ(c.current(), 1u);
  EXPECT_EQ(c.progress()[0].t_us, 2000);
  c.on_frame(0, sim::CanFrame::data_frame(0x702, {0x7F}), 2500);  // another data: no
  c.on_frame(0, sim::CanFrame::data_frame(0x702, {0x00}), 2700);
  c.on_frame(0, sim::CanFrame::data_frame(0x702, {0x00}), 2800);
  c.check(3000);
  EXPECT_EQ(c.current(), 2u);
  EXPECT_TRUE(c.progress()[1].done);
  EXPECT_EQ(c.progress()[1].t_us, 2700);  // when the frame crossed, not when it was checked
}

TEST(ExerciseChecker, OneWriteCompletesAChainOfTransitionSteps) {
  const auto e = parse("  - {title: a, text: t, goal: {transition: {node: dsv, to: DEVICE_MODE_ACTIVE}}}\n"
                       "  - {title: b, text: t, goal: {transition: {node: dsv, machine: dsp408, transition: TR_5}}}\n"
                       "  - {title: c, text: t, goal: {transition: {node: dsv, machine: dsp408, transition: TR_7, to: INIT}}}\n");
  Bench bench;
  bench.record(100, "dsp408", "HOLD", "DEVICE_MODE_ACTIVE", "TR_4");  // before the selection: not counted
  ExerciseChecker c(e, bench.binding());
  c.check(200);
  EXPECT_EQ(c.current(), 0u);
  bench.record(300, "nmt", "PRE-OPERATIONAL", "OPERATIONAL", "NMT 01h");
  bench.record(400, "dsp408", "HOLD", "DEVICE_MODE_ACTIVE", "TR_4");
  bench.record(900, "dsp408", "DEVICE_MODE_ACTIVE", "HOLD", "TR_5");
  bench.record(900, "dsp408", "HOLD", "DISABLED", "TR_6");
  bench.record(900, "dsp408", "DISABLED", "INIT", "TR_7");
  c.check(1000);
  EXPECT_EQ(c.current(), 3u);
  EXPECT_EQ(c.progress()[0].t_us, 400);
  EXPECT_EQ(c.progress()[1].t_us, 900);
  EXPECT_EQ(c.progress()[2].t_us, 900);
}

TEST(ExerciseChecker, TheWrongTransitionLeavesTheStepOpen) {
  const auto e = parse("  - {title: a, text: t, goal: {transition: {node: dsv, machine: dsp408, transition: TR_7, to: INIT}}}\n");
  Bench bench;
  ExerciseChecker c(e, bench.binding());
  bench.record(400, "dsp408", "DEVICE_MODE_ACTIVE", "INIT", "TR_567");
  bench.record(500, "dsp408.ch1", "DISABLED", "INIT", "TR_7");
  c.check(1000);
  EXPECT_EQ(c.current(), 0u);
  EXPECT_FALSE(c.progress()[0].done);
}

}  // namespace
