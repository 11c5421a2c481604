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
  EXPECT_EQ(r.finish(), "setting a: value 200 out of range [0, 100]");
  // The YAML reader's words for a value out of range; a number's limits in their shortest form.
  const std::map<std::string, std::string> real = {{"x", "1.5"}};
  SettingsReader r3(real);
  double x = 0.25;
  r3.get("x", x, 0.0, 0.5);
  EXPECT_EQ(r3.finish(), "setting x: value 1.5 out of range [0, 0.5]");
  EXPECT_EQ(x, 0.25);
  const std::map<std::string, std::string> unknown = {{"zzz", "1"}};
  SettingsReader r2(unknown);
  r2.get_uint("a", a, 0, 100);
  EXPECT_NE(r2.finish().find("unknown setting 'zzz'"), std::string::npos);
}

TEST(SettingsReader, UnknownNamesAreOneErrorListingTheKnownOnes) {
  const std::map<std::string, std::string> text = {{"sped", "3"}};
  SettingsReader r(text);
  int speed = 0, gain = 0;
  r.get_int("speed", speed, 0, 10);
  r.get_int("gain", gain, 0, 10);
  EXPECT_EQ(r.finish(), "unknown setting 'sped' (known: gain, speed)");
  EXPECT_EQ(unknown_setting("knob", {}), "unknown setting 'knob' (no settings)");
}

TEST(SettingsReader, IntegersAreDecimalOrHexNeverOctal) {
  const std::map<std::string, std::string> text = {{"a", "010"}, {"b", "0x1F"}, {"c", "-0x1"}, {"d", " 5"}};
  SettingsReader r(text);
  int a = 0, b = 0, c = 0;
  r.get_integer("a", a);
  r.get_integer("b", b);
  EXPECT_EQ(r.finish(), "unknown setting 'c' (known: a, b)");
  EXPECT_EQ(a, 10);
  EXPECT_EQ(b, 31);
  r.get_integer("c", c);
  EXPECT_EQ(r.finish(), "setting c='-0x1': expected an integer");
  std::uint8_t narrow = 7;
  const std::map<std::string, std::string> big = {{"n", "256"}};
  SettingsReader r2(big);
  r2.get_integer("n", narrow);
  EXPECT_EQ(r2.finish(), "setting n: value 256 out of range [0, 255]");
  EXPECT_EQ(narrow, 7);
}

TEST(SettingsReader, ADeprecatedNameReadsAsTheNewOneWithAWarning) {
  const std::map<std::string, std::string> old_name = {{"dither_freq", "50"}};
  SettingsReader r(old_name);
  r.deprecated("dither_freq", "dither_frequency");
  double hz = 100;
  r.get("dither_frequency", hz);
  EXPECT_EQ(r.finish(), "");
  EXPECT_EQ(hz, 50);
  EXPECT_EQ(r.warnings(), std::vector<std::string>{"setting 'dither_freq' is deprecated: use 'dither_frequency'"});

  const std::map<std::string, std::string> new_name = {{"dither_frequency", "60"}};
  SettingsReader r2(new_name);
  r2.deprecated("dither_freq", "dither_frequency");
  r2.get("dither_frequency", hz);
  EXPECT_EQ(r2.finish(), "");
  EXPECT_EQ(hz, 60);
  EXPECT_TRUE(r2.warnings().empty());

  const std::map<std::string, std::string> both = {{"dither_freq", "50"}, {"dither_frequency", "60"}};
  SettingsReader r3(both);
  r3.deprecated("dither_freq", "dither_frequency");
  r3.get("dither_frequency", hz);
  EXPECT_EQ(r3.finish(), "setting 'dither_freq' is the deprecated name of 'dither_frequency': give only 'dither_frequency'");
}

TEST(SettingsReader, AnOpenLowerBoundAProductsOwnCheckAndChoicesFromATable) {
  const std::map<std::string, std::string> given = {{"gain", "0"}, {"list", "a,b"}, {"mode", "fast"}};
  SettingsReader r(given);
  double gain = 4;
  r.get_above("gain", gain, 0, 10);
  EXPECT_EQ(r.finish(), "setting gain: value 0 out of range (0, 10]");
  EXPECT_EQ(gain, 4);

  SettingsReader r2(given);
  const std::string* list = r2.text("list");
  ASSERT_NE(list, nullptr);
  EXPECT_EQ(r2.text("absent"), nullptr);
  r2.reject("list", *list, "expected three names");
  int mode = 0;
  const std::vector<const char*> modes = {"slow", "fast"};
  r2.choose("mode", mode, modes);
  EXPECT_EQ(mode, 1);
  r2.get_above("gain", gain, -1, 10);
  EXPECT_EQ(gain, 0);
  EXPECT_EQ(r2.finish(), "setting list='a,b': expected three names");  // the first error
}

}  // namespace
}  // namespace devices
