// Legend of a standalone false-colour PNG: the plan on a white page with, below it, the
// quantity and unit, a horizontal colour bar of the scale with tick marks and values (the end
// labels say "<=" / ">=" where values are clamped, as the report's SVG legends do) and an
// optional note (e.g. the size of a cell). Text uses the built-in bitmap font (bitmap_font.h)
// at twice its size.
#pragma once

#include <string>

#include "dayphoton/report/colour_scale.h"
#include "dayphoton/study/image_files.h"

namespace dayphoton::report {

struct LegendImage {
  study::RgbaImage image;
  int plan_x = 0, plan_y = 0;                           ///< where the plan's pixel (0, 0) is
  int bar_x = 0, bar_y = 0, bar_width = 0, bar_height = 0;  ///< the colour bar
};

inline constexpr int LegendTextScale = 2;  ///< font pixels per bitmap-font pixel
inline constexpr int LegendMarginPx = 8;   ///< white margin around the plan and the legend

/// The plan (alpha-composited over white; pixels of the plan with alpha 0 become white) with
/// the legend below it; the image is as wide as the plan or the longest text line needs.
/// The bar's first column has the scale's colour at `min`, its last column the one at `max`.
LegendImage with_legend(const study::RgbaImage& plan, const ColourScale& scale, const std::string& title,
                        const std::string& note);

}  // namespace dayphoton::report
