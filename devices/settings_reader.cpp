#include "devices/settings_reader.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace devices {

namespace {

// Decimal or 0x-hex (never octal: "010" is ten), optionally negative when decimal.
bool parse_integer(const std::string& text, bool is_signed, std::int64_t& s, std::uint64_t& u) {
  const char* first = text.c_str();
  const char* last = first + text.size();
  const bool negative = first != last && *first == '-';
  if (negative && !is_signed) return false;
  int base = 10;
  if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    first += 2;
    base = 16;
  }
  if (first == last || (base == 16 && negative)) return false;
  const auto [ptr, ec] = is_signed ? std::from_chars(first, last, s, base) : std::from_chars(first, last, u, base);
  return ec == std::errc() && ptr == last;
}

std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

void SettingsReader::deprecated(const std::string& old_name, const std::string& name) { deprecated_[name] = old_name; }

const std::string* SettingsReader::find(const std::string& name) {
  known_.insert(name);
  const auto it = settings_.find(name);
  const auto old = deprecated_.find(name);
  if (old == deprecated_.end()) return it == settings_.end() ? nullptr : &it->second;
  const auto old_it = settings_.find(old->second);
  if (old_it == settings_.end()) return it == settings_.end() ? nullptr : &it->second;
  if (it != settings_.end()) {
    if (error_.empty()) error_ = "setting '" + old->second + "' is the deprecated name of '" + name + "': give only '" + name + "'";
    return nullptr;
  }
  warnings_.push_back("setting '" + old->second + "' is deprecated: use '" + name + "'");
  return &old_it->second;
}

void SettingsReader::fail(const std::string& name, const std::string& text, const std::string& expected) {
  if (error_.empty()) error_ = "setting " + name + "='" + text + "': expected " + expected;
}

// The same words as the scenario's YAML reader (sim/yaml_fields.h) for a value out of its range.
void SettingsReader::out_of_range(const std::string& name, const std::string& text, const std::string& min,
                                  const std::string& max) {
  if (error_.empty()) error_ = "setting " + name + ": value " + text + " out of range [" + min + ", " + max + "]";
}

void SettingsReader::get(const std::string& name, std::uint64_t& value, std::uint64_t min, std::uint64_t max) {
  const auto* text = find(name);
  if (!text) return;
  std::int64_t unused = 0;
  std::uint64_t v = 0;
  if (!parse_integer(*text, false, unused, v)) return fail(name, *text, "an integer");
  if (v < min || v > max) return out_of_range(name, *text, std::to_string(min), std::to_string(max));
  value = v;
}

void SettingsReader::get(const std::string& name, std::int64_t& value, std::int64_t min, std::int64_t max) {
  const auto* text = find(name);
  if (!text) return;
  std::int64_t v = 0;
  std::uint64_t unused = 0;
  if (!parse_integer(*text, true, v, unused)) return fail(name, *text, "an integer");
  if (v < min || v > max) return out_of_range(name, *text, std::to_string(min), std::to_string(max));
  value = v;
}

const std::string* SettingsReader::find_number(const std::string& name, double& v) {
  const auto* text = find(name);
  if (!text) return nullptr;
  char* end = nullptr;
  v = std::strtod(text->c_str(), &end);
  if (text->empty() || *end != '\0' || !std::isfinite(v)) {
    fail(name, *text, "a number");
    return nullptr;
  }
  return text;
}

void SettingsReader::get(const std::string& name, double& value, double min, double max) {
  double v = 0;
  const auto* text = find_number(name, v);
  if (!text) return;
  if (v < min || v > max) return out_of_range(name, *text, shortest(min), shortest(max));
  value = v;
}

void SettingsReader::get_above(const std::string& name, double& value, double min, double max) {
  double v = 0;
  const auto* text = find_number(name, v);
  if (!text) return;
  if (v <= min || v > max) {
    if (error_.empty()) error_ = "setting " + name + ": value " + *text + " out of range (" + shortest(min) + ", " + shortest(max) + "]";
    return;
  }
  value = v;
}

void SettingsReader::get(const std::string& name, double& value) {
  double v = 0;
  if (find_number(name, v)) value = v;
}

void SettingsReader::get(const std::string& name, bool& value) {
  const auto* text = find(name);
  if (!text) return;
  if (*text == "on" || *text == "true" || *text == "1" || *text == "yes") {
    value = true;
  } else if (*text == "off" || *text == "false" || *text == "0" || *text == "no") {
    value = false;
  } else {
    fail(name, *text, "on or off (true/false, yes/no, 1/0)");
  }
}

void SettingsReader::get(const std::string& name, std::string& value, std::size_t max_length) {
  const auto* text = find(name);
  if (!text) return;
  if (text->size() > max_length) return fail(name, *text, "at most " + std::to_string(max_length) + " characters");
  value = *text;
}

void SettingsReader::reject(const std::string& name, const std::string& text, const std::string& reason) {
  if (error_.empty()) error_ = "setting " + name + "='" + text + "': " + reason;
}

void SettingsReader::choose(const std::string& name, int& value, std::span<const char* const> choices) {
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
    bool deprecated_name = false;
    for (const auto& [current, old] : deprecated_) deprecated_name |= old == name;
    if (!known_.count(name) && !deprecated_name) return unknown_setting(name, known_);
  }
  return {};
}

std::string unknown_setting(const std::string& name, const std::set<std::string>& known) {
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  return "unknown setting '" + name + "' (" + (list.empty() ? "no settings" : "known: " + list) + ")";
}

}  // namespace devices
