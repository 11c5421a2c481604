// Parsing of repeated `key=value` command-line options.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace vplant {

/// "a=b" items into a map; false with `error` naming the bad item.
bool parse_key_values(const std::vector<std::string>& items, std::map<std::string, std::string>& out, std::string& error);
/// "a=1.5" items into a map of numbers.
bool parse_key_numbers(const std::vector<std::string>& items, std::map<std::string, double>& out, std::string& error);

}  // namespace vplant
