// A 5×7 bitmap font (with two rows below for descenders) for the overlay's text: printable ASCII,
// drawn by hand for this project, so the plugin needs no font library (Cairo, Pango) to say what it
// is doing.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace projtrack::gst {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 9;
// Bits of one row, the leftmost pixel in bit kGlyphWidth - 1.
using Glyph = std::array<std::uint8_t, kGlyphHeight>;

// The glyph of `c`; '?' for a character outside printable ASCII (' ' to '~').
const Glyph& glyph(char c);

// `utf8` as the font can draw it: the signs the tracker's messages use (×, –, —, ≤, ≥, ·, ², µ)
// by their ASCII look-alikes, any other character outside ASCII by one '?' (not one per byte).
std::string drawable(std::string_view utf8);

}  // namespace projtrack::gst
