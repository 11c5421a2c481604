// CiA 306 EDS reader: the INI sections of an EDS turned into an object dictionary, with every
// error and warning reported at its line (see eds.h for the error/warning split).
#pragma once

#include <optional>
#include <string_view>

#include "devices/canopen/eds.h"
#include "devices/canopen/eds_ini.h"

namespace canopen::eds_detail {

/// Reads `text` into a dictionary and `info`. Everything it finds goes to `diag`; the
/// dictionary is returned only when no error was reported.
std::optional<ObjectDictionary> read_eds(std::string_view text, Diagnostics& diag, EdsFileInfo& info);

}  // namespace canopen::eds_detail
