#include "devices/profiles/wandfluh/settings.h"

#include <charconv>
#include <cstdlib>

namespace wandfluh {

const std::string* Settings::find(const std::string& name) {
  used_.insert(name);
  const auto it = values_.find(name);
  return it == values_.end() ? nullptr : &it->second;
}

void Settings::fail(const std::string& message) {
  if (error_.empty()) error_ = message;
}

double Settings::number(const std::string& name, double fallback) {
  const auto* v = find(name);
  if (!v) return fallback;
  char* end = nullptr;
  const double d = std::strtod(v->c_str(), &end);
  if (v->empty() || end != v->c_str() + v->size()) {
    fail("setting '" + name + "': '" + *v + "' is not a number");
    return fallback;
  }
  return d;
}

std::int64_t Settings::integer(const std::string& name, std::int64_t fallback) {
  const auto* v = find(name);
  if (!v) return fallback;
  std::int64_t out = 0;
  const char* first = v->c_str();
  const char* last = first + v->size();
  int base = 10;
  if (v->size() > 2 && (*v)[0] == '0' && ((*v)[1] == 'x' || (*v)[1] == 'X')) {
    first += 2;
    base = 16;
  }
  const bool negative = first != last && *first == '-';
  const auto [ptr, ec] = std::from_chars(first, last, out, base);
  if (v->empty() || ec != std::errc() || ptr != last || (base == 16 && negative)) {
    fail("setting '" + name + "': '" + *v + "' is not an integer");
    return fallback;
  }
  return out;
}

bool Settings::flag(const std::string& name, bool fallback) {
  const auto* v = find(name);
  if (!v) return fallback;
  if (*v == "1" || *v == "true" || *v == "yes" || *v == "on") return true;
  if (*v == "0" || *v == "false" || *v == "no" || *v == "off") return false;
  fail("setting '" + name + "': '" + *v + "' is not a boolean (true/false)");
  return fallback;
}

std::string Settings::text(const std::string& name, const std::string& fallback) {
  const auto* v = find(name);
  return v ? *v : fallback;
}

std::string Settings::choice(const std::string& name, const std::string& fallback,
                             const std::vector<std::string>& choices) {
  const auto* v = find(name);
  if (!v) return fallback;
  for (const auto& c : choices)
    if (c == *v) return c;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  fail("setting '" + name + "': '" + *v + "' is not one of " + list);
  return fallback;
}

std::string Settings::finish() const {
  if (!error_.empty()) return error_;
  for (const auto& [name, value] : values_) {
    if (!used_.count(name)) return "unknown setting '" + name + "'";
  }
  return {};
}

}  // namespace wandfluh
