// The VT-VPCD object dictionary: the communication objects the manual lists (§3.1-§3.5; digest
// §2.7), the four RPDOs and TPDOs with the mapping the Bus Manager areas define, and the 116
// manufacturer objects of chapter 4. No 0x1010/0x1011: the card stores nothing written over the
// bus (manual §3: "All of the data are saved in the volatile memory (RAM)").
#pragma once

#include "devices/canopen/object_dictionary.h"
#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

/// Builds the dictionary for `settings` (whose areas must be valid: Settings::parse checks them).
canopen::ObjectDictionary build_dictionary(const Settings& settings);

}  // namespace vtvpcd
