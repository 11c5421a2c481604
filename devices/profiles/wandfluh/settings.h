// Typed access to DeviceOptions::settings (name → text) for the Wandfluh products: each getter
// names its default; finish() reports malformed values and names nobody asked for, so a typo in
// `--setting` is an error instead of a silently ignored knob.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace wandfluh {

class Settings {
 public:
  explicit Settings(const std::map<std::string, std::string>& values) : values_(values) {}

  double number(const std::string& name, double fallback);
  std::int64_t integer(const std::string& name, std::int64_t fallback);
  bool flag(const std::string& name, bool fallback);
  std::string text(const std::string& name, const std::string& fallback);
  /// One of `choices`.
  std::string choice(const std::string& name, const std::string& fallback, const std::vector<std::string>& choices);

  /// "" if every setting was known and well-formed, else the first problem.
  std::string finish() const;

 private:
  const std::string* find(const std::string& name);
  void fail(const std::string& message);

  const std::map<std::string, std::string>& values_;
  std::set<std::string> used_;
  std::string error_;
};

}  // namespace wandfluh
