// `matrix:` sweeps: the cases of a file, their names, the values written into each, and the
// file:line:col of every kind of bad matrix.
#include <gtest/gtest.h>

#include "engine/loading/scenario_cases.h"

using namespace scenario;

namespace {

const char* kBase = R"(name: sweep
nodes:
  - {name: ax, device: axis, node_id: 5, settings: {knob: "on"}}
plant:
  reference: true
clock: {duration: 1s, seed: 7}
faults:
  - {name: late, at: 500ms, device_fault: {node: ax, fault: jam}}
outputs: {trace: out/sweep.log, junit: out/sweep}
)";

std::string error_of(const std::string& text) {
  try {
    ScenarioCases::parse(text, "m.yaml", ".");
  } catch (const LoadError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ScenarioCases, AFileWithoutMatrixIsOneCaseNamedAsTheScenario) {
  const auto c = ScenarioCases::parse(kBase, "m.yaml", ".");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_FALSE(c.is_matrix());
  EXPECT_EQ(c.name(0), "sweep");
  EXPECT_EQ(c.load(0).outputs.trace, "out/sweep.log");
  EXPECT_EQ(c.output_path("x.csv", 0), "x.csv");
}

TEST(ScenarioCases, AThreeValueSweepIsThreeNamedCasesWithTheirValues) {
  const auto c = ScenarioCases::parse(std::string(kBase) + "matrix:\n  plant.cyl.viscous_friction: [1000, 2e3, 3000]\n",
                                      "m.yaml", ".");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c.name(0), "sweep[plant.cyl.viscous_friction=1000]");
  EXPECT_EQ(c.name(1), "sweep[plant.cyl.viscous_friction=2e3]");
  EXPECT_EQ(c.name(2), "sweep[plant.cyl.viscous_friction=3000]");
  for (std::size_t i = 0; i < 3; ++i) {
    const auto s = c.load(i);
    EXPECT_EQ(s.name, c.name(i));
    EXPECT_DOUBLE_EQ(s.plant["parameters"]["cyl.viscous_friction"].as<double>(), 1000.0 * static_cast<double>(i + 1));
  }
  EXPECT_EQ(c.find("sweep[plant.cyl.viscous_friction=2e3]"), 1u);
  EXPECT_FALSE(c.find("sweep"));
}

TEST(ScenarioCases, TheFirstKeyVariesSlowestAndEveryKindOfPathIsReached) {
  const auto c = ScenarioCases::parse(std::string(kBase) + R"(matrix:
  clock.seed: [1, 2]
  nodes.ax.settings.knob: ["on", "off"]
  faults.late.at: [1s, 2s]
)",
                                      "m.yaml", ".");
  ASSERT_EQ(c.size(), 8u);
  EXPECT_EQ(c.name(0), "sweep[clock.seed=1,nodes.ax.settings.knob=on,faults.late.at=1s]");
  EXPECT_EQ(c.name(1), "sweep[clock.seed=1,nodes.ax.settings.knob=on,faults.late.at=2s]");
  EXPECT_EQ(c.name(7), "sweep[clock.seed=2,nodes.ax.settings.knob=off,faults.late.at=2s]");
  const auto s = c.load(6);  // seed 2, knob off, at 1s
  EXPECT_EQ(s.clock.seed, 2u);
  EXPECT_EQ(s.nodes.at(0).settings.at("knob"), "off");
  ASSERT_TRUE(s.faults.at(0).at);
  EXPECT_EQ(*s.faults.at(0).at, sim::milliseconds(1000));
  // Each combination writes its own files.
  EXPECT_EQ(s.outputs.trace, "out/sweep.clock.seed=2,nodes.ax.settings.knob=off,faults.late.at=1s.log");
  EXPECT_EQ(s.outputs.junit, "out/sweep.clock.seed=2,nodes.ax.settings.knob=off,faults.late.at=1s");
  EXPECT_EQ(c.output_path("t/x.csv", 6), "t/x.clock.seed=2,nodes.ax.settings.knob=off,faults.late.at=1s.csv");
}

TEST(ScenarioCases, AKeyTheFileDoesNotHaveYetIsAdded) {
  const auto c = ScenarioCases::parse(std::string(kBase) + "matrix:\n  clock.tick: [1ms, 2ms]\n", "m.yaml", ".");
  EXPECT_EQ(c.load(1).clock.tick, sim::milliseconds(2));
}

TEST(ScenarioCases, APlantDescribedInFullHasItsComponentsParametersVaried) {
  const auto c = ScenarioCases::parse(R"(name: own
plant:
  components:
    - {type: tank, name: tank, parameters: {pressure: 0}}
    - {type: tank, name: sump}
clock: {duration: 1s}
matrix:
  plant.tank.pressure: [0, 1e5]
  plant.sump.pressure: [2e5]
)",
                                      "m.yaml", ".");
  ASSERT_EQ(c.size(), 2u);
  const auto s = c.load(1);
  EXPECT_DOUBLE_EQ(s.plant["components"][0]["parameters"]["pressure"].as<double>(), 1e5);
  EXPECT_DOUBLE_EQ(s.plant["components"][1]["parameters"]["pressure"].as<double>(), 2e5);
  EXPECT_EQ(error_of("plant: {components: [{type: tank, name: tank}]}\nmatrix: {plant.pump.alpha: [1]}\n"),
            "m.yaml:2:10: matrix: 'plant.pump.alpha': the plant has no component named 'pump'");
}

TEST(ScenarioCases, BadMatricesAreRejectedAtTheirLineAndColumn) {
  const std::string base = kBase;
  // line 10 is `matrix:`; its keys are on line 11, column 3
  EXPECT_EQ(error_of(base + "matrix:\n  clokc.seed: [1]\n"), "m.yaml:11:3: matrix: 'clokc.seed': the scenario has no 'clokc'");
  EXPECT_EQ(error_of(base + "matrix:\n  nodes.nope.node_id: [1]\n"),
            "m.yaml:11:3: matrix: 'nodes.nope.node_id': no item named 'nope' in the list");
  EXPECT_EQ(error_of(base + "matrix:\n  clock.duration.x: [1]\n"),
            "m.yaml:11:3: matrix: 'clock.duration.x': 'clock.duration' is a single value, not a mapping or a list");
  EXPECT_EQ(error_of(base + "matrix:\n  plant.cyl: [1]\n"), "m.yaml:11:3: matrix: 'plant.cyl': a plant parameter is plant.COMPONENT.PARAMETER");
  EXPECT_EQ(error_of(base + "matrix:\n  name: [a, b]\n"), "m.yaml:11:3: matrix: 'name' cannot be varied");
  EXPECT_EQ(error_of(base + "matrix:\n  clock..seed: [1]\n"), "m.yaml:11:3: matrix: 'clock..seed' is not a dotted path of keys");
  // A key added where the loader knows no such key: the loader's error, at the matrix key.
  EXPECT_EQ(error_of(base + "matrix:\n  clock.sed: [1]\n").rfind("m.yaml:11:3: unknown key 'sed' in clock (known: ", 0), 0u);
  // A value the loader refuses: at the value in the matrix.
  EXPECT_EQ(error_of(base + "matrix:\n  clock.seed: [-1]\n").substr(0, 15), "m.yaml:11:16: s");
  EXPECT_EQ(error_of(base + "matrix:\n  clock.seed: [1, 2, 1]\n"), "m.yaml:11:22: matrix: 'clock.seed': value '1' is given twice");
  EXPECT_EQ(error_of(base + "matrix:\n  clock.seed: []\n"), "m.yaml:11:15: matrix: 'clock.seed': expected a non-empty list of values");
  EXPECT_EQ(error_of(base + "matrix:\n  clock.seed: 3\n"), "m.yaml:11:15: matrix: 'clock.seed': expected a non-empty list of values");
  EXPECT_EQ(error_of(base + "matrix:\n  clock.seed: [[1]]\n"), "m.yaml:11:16: matrix: 'clock.seed': a value must be a single value");
  EXPECT_EQ(error_of(base + "matrix: {}\n"), "m.yaml:10:9: matrix: expected at least one key with a list of values");
  // 101 × 100 = 10 100 combinations > 10 000.
  std::string a = "[", b = "[";
  for (int i = 0; i < 101; ++i) a += (i ? "," : "") + std::to_string(i);
  for (int i = 0; i < 100; ++i) b += (i ? "," : "") + std::to_string(i);
  EXPECT_EQ(error_of(base + "matrix:\n  clock.seed: " + a + "]\n  faults.late.at: " + b + "]\n"),
            "m.yaml:11:3: matrix: more than 10000 combinations");
}
