#include "tools/vplant/key_value.h"

#include <cerrno>
#include <cstdlib>

namespace vplant {

bool parse_key_values(const std::vector<std::string>& items, std::map<std::string, std::string>& out, std::string& error) {
  for (const auto& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      error = "'" + item + "': expected name=value";
      return false;
    }
    out[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return true;
}

bool parse_key_numbers(const std::vector<std::string>& items, std::map<std::string, double>& out, std::string& error) {
  std::map<std::string, std::string> text;
  if (!parse_key_values(items, text, error)) return false;
  for (const auto& [key, value] : text) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || errno == ERANGE) {
      error = "'" + key + "=" + value + "': value is not a number";
      return false;
    }
    out[key] = v;
  }
  return true;
}

}  // namespace vplant
