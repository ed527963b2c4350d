// BitmapFont: a tiny built-in 5 x 7 pixel font for the text of the standalone PNG images
// (legend titles, tick values), so that no font library is needed. Upper- and lower-case
// letters (so that units read right: "m" is not "M", mega), digits and the punctuation of
// quantity names and numbers; any other character is drawn as '?'. Lower-case letters with a
// descender (g, j, p, q, y) are raised to fit the 7 rows, as on dot-matrix displays. Each glyph sits in a 6 x 9 cell (one column and two rows of
// spacing) and is scaled by a whole factor.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "dayphoton/study/image_files.h"

namespace dayphoton::report {

inline constexpr int GlyphWidth = 5, GlyphHeight = 7;
inline constexpr int GlyphAdvance = 6, GlyphLineHeight = 9;  ///< cell of one glyph, unscaled px

/// Whether pixel (x, y) of character `c`'s glyph is set (x < GlyphWidth, y < GlyphHeight,
/// y = 0 at the top).
bool glyph_pixel(char c, int x, int y);

/// Width and height in pixels of `text` drawn at `scale` (one line; no trailing spacing).
int text_width_px(const std::string& text, int scale);
inline int text_height_px(int scale) { return GlyphHeight * scale; }

/// Draw `text` with its top-left corner at (x, y), each font pixel a `scale` x `scale` block
/// of `colour`; pixels outside the image are skipped.
void draw_text(study::RgbaImage& image, int x, int y, const std::string& text, int scale,
               std::array<std::uint8_t, 4> colour);

}  // namespace dayphoton::report
