#include "tools/vplant/exercise_folder.h"

#include <sys/stat.h>
#include <unistd.h>

namespace vplant {

std::string default_exercises_dir() {
  char exe[4096];
  const auto n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    std::string path(exe, static_cast<std::size_t>(n));
    const auto slash = path.rfind('/');
    const std::string installed = path.substr(0, slash == std::string::npos ? 0 : slash) + "/../share/vplant/exercises";
    struct stat st{};
    if (::stat(installed.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return installed;
  }
  return VPLANT_SOURCE_EXERCISES;
}

}  // namespace vplant
