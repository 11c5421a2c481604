#include "tools/vplant/text_output.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "tools/vplant/exit_codes.h"

namespace vplant {

int write_text_output(const char* command, const std::string& text, const std::string& path) {
  const bool to_stdout = path.empty() || path == "-";
  std::FILE* f = to_stdout ? stdout : std::fopen(path.c_str(), "w");
  errno = 0;
  bool ok = f != nullptr && std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  const int err = errno;
  if (f && !to_stdout && std::fclose(f) != 0) ok = false;
  if (ok) return kExitOk;
  std::fprintf(stderr, "%s: cannot write '%s': %s\n", command, to_stdout ? "stdout" : path.c_str(),
               std::strerror(err != 0 ? err : errno != 0 ? errno : EIO));
  return kExitBadInput;
}

}  // namespace vplant
