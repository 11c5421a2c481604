// The EDS entry points: text and file loading, the checker, error messages. The work is done by
// eds_ini (INI layer), eds_value (value syntax), eds_reader and eds_writer.
#include "devices/canopen/eds.h"

#include <cerrno>
#include <cstring>

#include "devices/canopen/eds_ini.h"
#include "devices/canopen/eds_reader.h"
#include "sim/file_reader.h"

namespace canopen {

namespace {

bool read_file(const std::string& path, std::string& text, EdsError& error) {
  std::string reason;
  switch (sim::read_input_file(path, text, reason)) {
    case sim::ReadStatus::Ok: return true;
    case sim::ReadStatus::Missing: reason = std::string("cannot open: ") + std::strerror(ENOENT); break;
    case sim::ReadStatus::Failed: break;
  }
  error = EdsError{{path, 0, 0}, reason, false};
  return false;
}

}  // namespace

std::optional<ObjectDictionary> parse_eds(std::string_view text, const std::string& file_name, EdsError& error,
                                          EdsFileInfo* info, std::vector<EdsError>* warnings, EdsStrictness strictness) {
  eds_detail::Diagnostics diag(file_name, strictness == EdsStrictness::Strict);
  EdsFileInfo scratch;
  auto od = eds_detail::read_eds(text, diag, info ? *info : scratch);
  if (warnings) {
    warnings->clear();
    for (auto& e : diag.sorted())
      if (e.warning) warnings->push_back(std::move(e));
  }
  if (const EdsError* first = diag.first_error()) {
    error = *first;
    return std::nullopt;
  }
  return od;
}

std::optional<ObjectDictionary> load_eds(const std::string& path, EdsError& error, EdsFileInfo* info,
                                         std::vector<EdsError>* warnings, EdsStrictness strictness) {
  std::string text;
  if (!read_file(path, text, error)) return std::nullopt;
  return parse_eds(text, path, error, info, warnings, strictness);
}

std::vector<EdsError> check_eds(std::string_view text, const std::string& file_name, EdsStrictness strictness) {
  eds_detail::Diagnostics diag(file_name, strictness == EdsStrictness::Strict);
  EdsFileInfo info;
  (void)eds_detail::read_eds(text, diag, info);
  return diag.sorted();
}

std::vector<EdsError> check_eds_file(const std::string& path, EdsStrictness strictness) {
  std::string text;
  EdsError error;
  if (!read_file(path, text, error)) return {error};
  return check_eds(text, path, strictness);
}

}  // namespace canopen
