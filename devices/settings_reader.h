// Reads a product's configuration settings (DeviceOptions::settings, text by name) into typed
// values with their defaults and ranges, and rejects unknown names, so every knob of a docs page
// is parsed the same way: numbers in decimal or 0x-hex, booleans as on/off/true/false/1/0,
// choices from a fixed list.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <set>
#include <string>

namespace devices {

class SettingsReader {
 public:
  explicit SettingsReader(const std::map<std::string, std::string>& settings) : settings_(settings) {}

  void get(const std::string& name, std::uint64_t& value, std::uint64_t min, std::uint64_t max);
  void get(const std::string& name, std::int64_t& value, std::int64_t min, std::int64_t max);
  void get(const std::string& name, double& value, double min, double max);
  void get(const std::string& name, bool& value);
  void get(const std::string& name, std::string& value, std::size_t max_length);
  /// One of `choices`; `value` receives its position in the list.
  void choose(const std::string& name, int& value, std::initializer_list<const char*> choices);

  template <typename T>
  void get_uint(const std::string& name, T& value, std::uint64_t min, std::uint64_t max) {
    std::uint64_t v = value;
    get(name, v, min, max);
    value = static_cast<T>(v);
  }
  template <typename T>
  void get_int(const std::string& name, T& value, std::int64_t min, std::int64_t max) {
    std::int64_t v = value;
    get(name, v, min, max);
    value = static_cast<T>(v);
  }

  /// The first error, or an unknown setting; empty when everything was read.
  std::string finish() const;

 private:
  const std::string* find(const std::string& name);
  void fail(const std::string& name, const std::string& text, const std::string& expected);

  const std::map<std::string, std::string>& settings_;
  std::set<std::string> known_;
  std::string error_;
};

}  // namespace devices
