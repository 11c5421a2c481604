// A fresh path under the tests' temporary directory, for files a test writes (stores, traces,
// scenario files). ctest runs every test case as its own process, several at once, so a fixed
// name is shared by concurrent cases and one overwrites the other's file; mkstemps makes the name
// unique. The file is removed again: a test sees nothing at the path until it writes there.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace vtest {

inline std::string unique_temp_path(std::string_view stem, std::string_view suffix = {}) {
  std::string path = ::testing::TempDir();
  if (!path.empty() && path.back() != '/') path += '/';
  path.append(stem).append("-XXXXXX").append(suffix);
  const int fd = ::mkstemps(path.data(), static_cast<int>(suffix.size()));
  if (fd < 0) {
    ADD_FAILURE() << "cannot create a temporary file like " << path;
    return path;
  }
  ::close(fd);
  std::remove(path.c_str());
  return path;
}

}  // namespace vtest
