// Every plant signal says how an engineer reads it: the display unit its component type chose
// (bar for Pa, mm for m, rpm for rad/s, l/min for m^3/s, % for fractions), and the plant's ports
// carry it to the API.
#include <gtest/gtest.h>

#include <map>
#include <numbers>
#include <string>

#include "plant/component_type.h"
#include "plant/plant.h"
#include "plant/reference_plant.h"

namespace plant {
namespace {

TEST(SignalDisplay, EveryComponentSignalHasTheDisplayUnitOfItsQuantity) {
  const std::map<std::string, std::string> by_si{{"Pa", "bar"}, {"m", "mm"},     {"m/s", "mm/s"}, {"rad/s", "rpm"},
                                                 {"m^3/s", "l/min"}, {"1", "%"}, {"N", "kN"}};
  for (const ComponentType* type : component_types()) {
    for (const auto& s : type->signals) {
      const std::string where = std::string(type->name) + "." + std::string(s.name);
      ASSERT_FALSE(s.display.unit.empty()) << where;
      EXPECT_GT(s.display.scale, 0.0) << where;
      EXPECT_EQ(s.display.offset, 0.0) << where;
      const auto it = by_si.find(std::string(s.unit));
      if (it != by_si.end()) {
        EXPECT_EQ(s.display.unit, it->second) << where;
      }
    }
  }
}

TEST(SignalDisplay, ThePlantsPortsCarryTheirComponentsDisplayUnit) {
  Plant p(reference_plant_description());
  const auto* position = sim::find_port(p.ports(), "cyl.position");
  ASSERT_NE(position, nullptr);
  EXPECT_EQ(position->unit, "m");
  EXPECT_EQ(position->display.unit, "mm");
  EXPECT_DOUBLE_EQ(position->display.scale, 1e3);
  const auto* speed = sim::find_port(p.ports(), "shaft.speed");
  ASSERT_NE(speed, nullptr);
  EXPECT_EQ(speed->display.unit, "rpm");
  for (const auto& port : p.ports()) EXPECT_FALSE(port.display.unit.empty()) << port.name;
}

TEST(SignalDisplay, ScalesTurnSiIntoTheDisplayUnit) {
  EXPECT_DOUBLE_EQ(1e5 * sim::display::bar.scale, 1.0);                      // 1 bar = 1e5 Pa
  EXPECT_DOUBLE_EQ(0.25 * sim::display::mm.scale, 250.0);                    // 0.25 m
  EXPECT_NEAR(2 * std::numbers::pi * sim::display::rpm.scale, 60.0, 1e-12);  // 1 turn/s = 60 rpm
  EXPECT_NEAR(1e-3 / 60 * sim::display::l_per_min.scale, 1.0, 1e-12);        // 1 l/min
  EXPECT_NEAR(std::numbers::pi * sim::display::degree.scale, 180.0, 1e-12);
  EXPECT_NEAR(4 * std::numbers::pi * sim::display::turns.scale, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(0.5 * sim::display::percent.scale, 50.0);
}

}  // namespace
}  // namespace plant
