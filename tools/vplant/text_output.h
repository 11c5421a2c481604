// Writing a generated text (EDS, DCF) to stdout or a file, with write errors reported.
#pragma once

#include <string>

namespace vplant {

/// Writes `text` to `path` ("" or "-" = stdout). Returns kExitOk, or kExitBadInput after printing
/// "`command`: cannot write 'PATH': reason" when any byte did not reach the file.
int write_text_output(const char* command, const std::string& text, const std::string& path);

}  // namespace vplant
