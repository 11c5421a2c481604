// vplant public API: the one exception type. A scenario, signal or fault the library rejects
// carries the same `file:line:col: reason` text `vplant run` prints.
#pragma once

#include <stdexcept>
#include <string>

namespace vplant {

class Error : public std::runtime_error {
 public:
  Error(std::string file, int line, int column, std::string reason, const std::string& what)
      : std::runtime_error(what), file_(std::move(file)), line_(line), column_(column), reason_(std::move(reason)) {}

  /// The file (or "<string>", "<signal>", "<fault>" for text given in code); line and column
  /// are 1-based, 0 when unknown.
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  /// The reason alone, without the position.
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string reason_;
};

}  // namespace vplant
