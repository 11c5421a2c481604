// Where `--exercises` looks by default (vplant run, vplant classroom; docs/exercises.md).
#pragma once

#include <string>

namespace vplant {

/// The shipped exercises: beside an installed binary (PREFIX/bin → PREFIX/share/vplant/exercises),
/// else the source tree's folder this binary was built from.
std::string default_exercises_dir();

}  // namespace vplant
