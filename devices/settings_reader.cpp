#include "devices/settings_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace devices {

const std::string* SettingsReader::find(const std::string& name) {
  known_.insert(name);
  const auto it = settings_.find(name);
  return it == settings_.end() ? nullptr : &it->second;
}

void SettingsReader::fail(const std::string& name, const std::string& text, const std::string& expected) {
  if (error_.empty()) error_ = "setting " + name + "='" + text + "': expected " + expected;
}

void SettingsReader::get(const std::string& name, std::uint64_t& value, std::uint64_t min, std::uint64_t max) {
  const auto* text = find(name);
  if (!text) return;
  const std::string range = std::to_string(min) + ".." + std::to_string(max);
  if (text->empty() || (*text)[0] == '-') return fail(name, *text, "an integer in " + range);
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text->c_str(), &end, 0);
  if (errno != 0 || *end != '\0' || v < min || v > max) return fail(name, *text, "an integer in " + range);
  value = v;
}

void SettingsReader::get(const std::string& name, std::int64_t& value, std::int64_t min, std::int64_t max) {
  const auto* text = find(name);
  if (!text) return;
  const std::string range = std::to_string(min) + ".." + std::to_string(max);
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text->c_str(), &end, 0);
  if (text->empty() || errno != 0 || *end != '\0' || v < min || v > max) return fail(name, *text, "an integer in " + range);
  value = v;
}

void SettingsReader::get(const std::string& name, double& value, double min, double max) {
  const auto* text = find(name);
  if (!text) return;
  char* end = nullptr;
  const double v = std::strtod(text->c_str(), &end);
  if (text->empty() || *end != '\0' || !std::isfinite(v) || v < min || v > max) {
    return fail(name, *text, "a number in " + std::to_string(min) + ".." + std::to_string(max));
  }
  value = v;
}

void SettingsReader::get(const std::string& name, bool& value) {
  const auto* text = find(name);
  if (!text) return;
  if (*text == "on" || *text == "true" || *text == "1" || *text == "yes") {
    value = true;
  } else if (*text == "off" || *text == "false" || *text == "0" || *text == "no") {
    value = false;
  } else {
    fail(name, *text, "on or off");
  }
}

void SettingsReader::get(const std::string& name, std::string& value, std::size_t max_length) {
  const auto* text = find(name);
  if (!text) return;
  if (text->size() > max_length) return fail(name, *text, "at most " + std::to_string(max_length) + " characters");
  value = *text;
}

void SettingsReader::choose(const std::string& name, int& value, std::initializer_list<const char*> choices) {
  const auto* text = find(name);
  if (!text) return;
  int i = 0;
  std::string list;
  for (const char* c : choices) {
    if (*text == c) {
      value = i;
      return;
    }
    list += (list.empty() ? "" : " | ") + std::string(c);
    ++i;
  }
  fail(name, *text, list);
}

std::string SettingsReader::finish() const {
  if (!error_.empty()) return error_;
  for (const auto& [name, text] : settings_) {
    if (!known_.count(name)) {
      std::string list;
      for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
      return "unknown setting '" + name + "' (settings: " + list + ")";
    }
  }
  return {};
}

}  // namespace devices
