#include "devices/settings_reader.h"

#include <gtest/gtest.h>

namespace devices {
namespace {

TEST(SettingsReader, TypedValuesDefaultsAndUnknownNames) {
  const std::map<std::string, std::string> text = {{"a", "0x10"}, {"b", "-3"}, {"c", "off"}, {"d", "abort"}};
  SettingsReader r(text);
  std::uint32_t a = 1;
  int b = 0, d = 0;
  bool c = true;
  double e = 2.5;
  r.get_uint("a", a, 0, 100);
  r.get_int("b", b, -5, 5);
  r.get("c", c);
  r.choose("d", d, {"alarm", "abort"});
  r.get("e", e, 0, 10);
  EXPECT_EQ(r.finish(), "");
  EXPECT_EQ(a, 16u);
  EXPECT_EQ(b, -3);
  EXPECT_FALSE(c);
  EXPECT_EQ(d, 1);
  EXPECT_EQ(e, 2.5);
}

TEST(SettingsReader, ErrorsNameTheSetting) {
  const std::map<std::string, std::string> text = {{"a", "200"}, {"zzz", "1"}};
  SettingsReader r(text);
  std::uint32_t a = 1;
  r.get_uint("a", a, 0, 100);
  EXPECT_NE(r.finish().find("setting a='200'"), std::string::npos);
  const std::map<std::string, std::string> unknown = {{"zzz", "1"}};
  SettingsReader r2(unknown);
  r2.get_uint("a", a, 0, 100);
  EXPECT_NE(r2.finish().find("unknown setting 'zzz'"), std::string::npos);
}

}  // namespace
}  // namespace devices
