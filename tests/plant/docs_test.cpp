// docs/plant.md documents every component type, parameter and signal the code has.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "plant/component_type.h"

namespace plant {
namespace {

TEST(PlantDocs, NameEveryTypeParameterAndSignal) {
  std::ifstream file(std::string(VPLANT_SOURCE_DIR) + "/docs/plant.md");
  ASSERT_TRUE(file) << "docs/plant.md missing";
  std::stringstream text;
  text << file.rdbuf();
  const std::string doc = text.str();
  for (const ComponentType* type : component_types()) {
    const std::string heading = "#### `" + std::string(type->name) + "`";
    const auto at = doc.find(heading);
    ASSERT_NE(at, std::string::npos) << heading;
    const auto end = doc.find("#### `", at + heading.size());
    const std::string section = doc.substr(at, end == std::string::npos ? std::string::npos : end - at);
    for (const auto& p : type->parameters)
      EXPECT_NE(section.find("| `" + std::string(p.name) + "` |"), std::string::npos) << type->name << "." << p.name;
    for (const auto& s : type->signals)
      EXPECT_NE(section.find("| `" + std::string(s.name) + "` |"), std::string::npos) << type->name << "." << s.name;
    for (const auto& c : type->connectors)
      EXPECT_NE(section.find("`" + std::string(c.name) + "`"), std::string::npos) << type->name << "." << c.name;
  }
}

}  // namespace
}  // namespace plant
