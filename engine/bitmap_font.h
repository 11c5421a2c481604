// A 5×7 pixel font for printable ASCII (the classic HD44780-style glyphs), for plot labels.
#pragma once

#include <cstdint>

namespace scenario {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;

/// Five columns of a glyph, bit 0 = top row; '?' for characters outside 0x20..0x7E.
const std::uint8_t* glyph(char c);

}  // namespace scenario
