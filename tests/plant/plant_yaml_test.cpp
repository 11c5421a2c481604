// The plant description in YAML: the shipped reference file equals the built-in reference plant,
// and each kind of error is reported at its file:line:col.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <fstream>
#include <string>

#include "plant/plant_yaml.h"
#include "plant/reference_plant.h"
#include "plant_test_support.h"
#include "tests/support/temp_path.h"

namespace plant {
namespace {

using namespace plant::testing;

const std::string kReferenceFile = std::string(VPLANT_SOURCE_DIR) + "/scenarios/plant/reference-plant.plant.yaml";

TEST(PlantYaml, ReferenceFileBuildsTheSamePlantAsTheBuiltInDescription) {
  const PlantDescription from_file = load_plant_file(kReferenceFile);
  const PlantDescription built_in = reference_plant_description();
  EXPECT_TRUE(equivalent(from_file, built_in));
  // Same plant, not just the same data: identical outputs, bit for bit, under the same inputs.
  Plant a(from_file), b(built_in);
  ASSERT_EQ(a.ports().size(), b.ports().size());
  long mismatches = 0;
  run(a, 2.0, [&](double t) {
    // Both plants have taken the same number of steps here.
    for (std::size_t i = 0; i < a.ports().size(); ++i)
      mismatches += std::memcmp(a.ports()[i].value, b.ports()[i].value, sizeof(double)) != 0;
    for (Plant* p : {&a, &b}) {
      port(*p, "pump.pilot_command") = 4.0 * (0.5 - port(*p, "pump.swivel_angle"));
      port(*p, "valve_cyl.solenoid_a_current") = t > 0.2 ? 0.5 : 0.0;
      port(*p, "valve_motor.solenoid_b_current") = t > 0.5 ? 0.8 : 0.0;
    }
    b.step(sim::Time{}, sim::milliseconds(1));  // run() steps a right after this
  });
  EXPECT_EQ(mismatches, 0);
}

TEST(PlantYaml, EmittedYamlParsesBackToTheSameDescription) {
  const PlantDescription d = reference_plant_description();
  const PlantDescription back = parse_plant_description(YAML::Load(to_yaml(d))["plant"], "emitted");
  EXPECT_TRUE(equivalent(d, back));
}

// Parses `text` (a whole file with a `plant:` section) and returns the error message.
std::string error_of(const std::string& text) {
  const vtest::TempPath temp("bad", ".plant.yaml");
  const std::string& path = temp.str();
  std::ofstream(path) << text;
  try {
    load_plant_file(path);
  } catch (const DescriptionError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ":", 0), 0u) << message;
    return message.substr(path.size() + 1);  // "line:col: reason"
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return {};
}

const char* kMinimal = R"(plant:
  components:
    - type: fluid
      name: oil
    - type: tank
      name: tank
    - type: volume
      name: line
      parameters:
        volume: 0.001
    - type: relief_valve
      name: relief
  connections:
    - name: supply
      ports: [line.port, relief.P]
    - name: return
      ports: [tank.port, relief.T]
)";

TEST(PlantYaml, MinimalFileIsAccepted) {
  const vtest::TempPath path("good", ".plant.yaml");
  std::ofstream(path.str()) << kMinimal;
  const PlantDescription d = load_plant_file(path);
  EXPECT_EQ(d.components.size(), 4u);
  EXPECT_NO_THROW(Plant{d});
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PlantYaml, UnknownComponentTypeIsReportedAtTheType) {
  EXPECT_EQ(error_of(with(kMinimal, "type: relief_valve", "type: relief_vlave")),
            "11:13: unknown component type 'relief_vlave'");
}

TEST(PlantYaml, UnknownParameterIsReportedAtItsName) {
  EXPECT_EQ(error_of(with(kMinimal, "volume: 0.001", "volme: 0.001")),
            "10:9: unknown parameter 'volme' for component type 'volume'");
}

TEST(PlantYaml, OutOfRangeValueIsReportedAtTheValue) {
  EXPECT_EQ(error_of(with(kMinimal, "volume: 0.001", "volume: -0.001")),
            "10:17: parameter 'volume' = -0.001 out of range: must be > 0 m^3");
  EXPECT_EQ(error_of(with(kMinimal, "volume: 0.001", "volume: 1 litre")),
            "10:17: parameter 'volume': '1 litre' is not a number");
}

TEST(PlantYaml, DuplicateComponentNameIsReportedAtTheSecondName) {
  EXPECT_EQ(error_of(with(kMinimal, "name: relief", "name: line")), "12:13: duplicate component name 'line'");
}

TEST(PlantYaml, ConnectionToAMissingComponentIsReportedAtThePort) {
  EXPECT_EQ(error_of(with(kMinimal, "[line.port, relief.P]", "[line.port, valve.P]")),
            "15:26: connection 'supply': no component named 'valve'");
}

TEST(PlantYaml, ConnectionToAMissingPortIsReportedAtThePort) {
  EXPECT_EQ(error_of(with(kMinimal, "[line.port, relief.P]", "[line.port, relief.A]")),
            "15:26: connection 'supply': component 'relief' (relief_valve) has no port 'A'");
}

TEST(PlantYaml, OtherStructuralErrorsArePlacedToo) {
  EXPECT_EQ(error_of(with(kMinimal, "      name: oil", "      name: oil\n      colour: amber")),
            "5:7: unknown key 'colour' in a component (known: type, name, parameters)");
  EXPECT_EQ(error_of(with(kMinimal, "[tank.port, relief.T]", "[tank.port]")), "11:7: port 'relief.T' is not connected");
  EXPECT_EQ(error_of(with(kMinimal, "[tank.port, relief.T]", "[tank.port, relief.T, relief.P]")),
            "17:36: port 'relief.P' is connected twice");
  EXPECT_EQ(error_of("plant:\n  components: [\n"), "3:1: YAML syntax error: end of sequence flow not found");
}

// The plant reads its description with the engine's strict reader (sim/yaml_fields.h): the same
// wording for a duplicate key, a missing key, a key misplaced in a section, a value of the wrong kind.
TEST(PlantYaml, TheSharedReaderPlacesEveryFieldError) {
  EXPECT_EQ(error_of(with(kMinimal, "      name: oil", "      name: oil\n      name: oil2")),
            "5:7: a component: duplicate key 'name'");
  EXPECT_EQ(error_of(with(kMinimal, "    - type: tank\n      name: tank\n", "    - name: tank\n")),
            "5:7: a component: missing key 'type'");
  EXPECT_EQ(error_of("plant:\n  connections: []\n"), "2:3: plant: missing key 'components'");
  EXPECT_EQ(error_of(with(kMinimal, "plant:\n", "plant:\n  solver: {max_stp: 0.001}\n")),
            "2:12: unknown key 'max_stp' in plant.solver (known: max_step)");
  EXPECT_EQ(error_of(with(kMinimal, "  connections:\n", "  connection:\n")),
            "13:3: unknown key 'connection' in plant (known: solver, components, connections)");
  EXPECT_EQ(error_of(with(kMinimal, "volume: 0.001", "volume: [1]")), "10:17: parameter 'volume': expected a scalar value");
  EXPECT_EQ(error_of(with(kMinimal, "volume: 0.001", "volume: 0.001\n        volume: 0.002")),
            "11:9: parameters: duplicate key 'volume'");
  EXPECT_EQ(error_of(with(kMinimal, "ports: [line.port, relief.P]", "ports: line.port")),
            "15:14: ports: expected a list of ports");
}

// yaml-cpp stops at its depth limit with the message "bad file"; the reason must say what is wrong.
TEST(PlantYaml, DeepNestingIsReportedAsNestingNotAsABadFile) {
  const std::string message = error_of("plant:\n  components: " + std::string(100000, '[') + "\n");
  EXPECT_NE(message.find(": nesting deeper than"), std::string::npos) << message;
}

TEST(PlantYaml, OnlyARegularFileIsRead) {
  const vtest::TempPath dir("plant-fifo");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  const std::string fifo = dir.str() + "/plant.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);  // a blocking open() would wait for a writer forever
  try {
    load_plant_file(fifo);
    ADD_FAILURE() << "a FIFO was read";
  } catch (const DescriptionError& e) {
    EXPECT_EQ(std::string(e.what()), fifo + ": not a regular file (a FIFO)");
  }
}

}  // namespace
}  // namespace plant
