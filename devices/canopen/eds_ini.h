// The INI layer of CiA 306 EDS files: sections and key=value lines with their line numbers, and
// the diagnostics list (errors and warnings) every later stage reports into. Section and key
// names are case-insensitive; `;` starts a comment line; CRLF and a UTF-8 BOM are accepted.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "devices/canopen/eds.h"

namespace canopen::eds_detail {

class Diagnostics {
 public:
  explicit Diagnostics(std::string file, bool strict = true) : file_(std::move(file)), strict_(strict) {}
  void error(int line, std::string reason);
  /// An error in the INI layer itself: it can make later checks fail at other lines, so the
  /// first syntax error is what parse_eds() reports when there is one.
  void syntax_error(int line, std::string reason);
  void warning(int line, std::string reason);
  /// A CiA 306 deviation that writing tools produce and masters tolerate (docs/runtime.md, "EDS
  /// files"): strict, an error; otherwise a warning saying how the file is read (`reading`).
  void deviation(int line, const std::string& reason, const std::string& reading);
  bool strict() const { return strict_; }
  bool has_errors() const { return errors_ > 0; }
  std::size_t error_count() const { return static_cast<std::size_t>(errors_); }
  /// Errors and warnings in line order (stable: same line keeps discovery order).
  std::vector<EdsError> sorted() const;
  /// The first syntax error, else the error with the lowest line (nullptr if none).
  const EdsError* first_error() const;

 private:
  std::string file_;
  bool strict_;
  std::vector<EdsError> items_;
  std::vector<bool> syntax_;
  int errors_ = 0;
  int syntax_errors_ = 0;
};

struct IniKey {
  std::string name;   ///< as written
  std::string upper;  ///< upper-case, for lookup
  std::string value;  ///< trimmed
  int line = 0;
};

struct IniSection {
  std::string name;
  std::string upper;
  int line = 0;
  std::vector<IniKey> keys;
  mutable std::vector<bool> used;  ///< keys consumed by the reader (the rest are "unknown")

  const IniKey* find(std::string_view upper_key) const;
  /// find() that marks the key as understood.
  const IniKey* take(std::string_view upper_key) const;
};

struct IniFile {
  std::vector<IniSection> sections;
  int line_count = 0;
  const IniSection* find(std::string_view upper_name) const;
};

/// Splits `text` into sections. Syntax errors, keys outside a section and duplicate
/// sections/keys are reported; a duplicate section's content is dropped.
IniFile lex_ini(std::string_view text, Diagnostics& diag);

std::string to_upper(std::string_view s);
std::string_view trim(std::string_view s);

}  // namespace canopen::eds_detail
