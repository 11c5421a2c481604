// The whole content of a file as a string (EDS exports, traces, CSVs a test compares); empty if
// it cannot be read.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace vtest {

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace vtest
