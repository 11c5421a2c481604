// A fresh path under the tests' temporary directory, for files a test writes (stores, traces,
// scenario files). ctest runs every test case as its own process, several at once, so a fixed
// name is shared by concurrent cases and one overwrites the other's file; mkstemps makes the name
// unique. The file is removed again: a test sees nothing at the path until it writes there.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

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

/// A unique_temp_path() that is removed when it goes out of scope, also when a failed assertion
/// returns early: the file, a directory with its contents, and the ".tmp" sibling an atomic save
/// leaves behind when it is killed.
class TempPath {
 public:
  explicit TempPath(std::string_view stem, std::string_view suffix = {}) : path_(unique_temp_path(stem, suffix)) {}
  TempPath(const TempPath&) = delete;
  TempPath& operator=(const TempPath&) = delete;
  ~TempPath() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    std::filesystem::remove(path_ + ".tmp", ec);
  }
  const std::string& str() const { return path_; }
  operator const std::string&() const { return path_; }  // NOLINT: used where a path string is expected
  const char* c_str() const { return path_.c_str(); }

 private:
  std::string path_;
};

}  // namespace vtest
