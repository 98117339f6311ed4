// A 5×7 bitmap font (with two rows below for descenders) for the overlay's text: printable ASCII,
// drawn by hand for this project, so the plugin needs no font library (Cairo, Pango) to say what it
// is doing.
#pragma once

#include <array>
#include <cstdint>

namespace projtrack::gst {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 9;
// Bits of one row, the leftmost pixel in bit kGlyphWidth - 1.
using Glyph = std::array<std::uint8_t, kGlyphHeight>;

// The glyph of `c`; '?' for a character outside printable ASCII (' ' to '~').
const Glyph& glyph(char c);

}  // namespace projtrack::gst
