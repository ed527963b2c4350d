// The sky fisheye PNG (report/sky_picture.h): the letters N, S, E, W (east LEFT: the sky seen
// from below) sit glyph for glyph in the margin on the axes, the fisheye keeps its false colour
// inside the horizon circle, and the legend below it has the scale's end colours at the bar's
// ends and the unit in its title.
#include "dayphoton/report/sky_picture.h"

#include <gtest/gtest.h>

#include <cmath>

#include "dayphoton/report/bitmap_font.h"
#include "dayphoton/report/image_legend.h"

using namespace dayphoton;
using namespace dayphoton::report;

namespace {

/// A 64 x 64 fisheye of uniform luminance `cd_m2` inside the circle.
study::FloatImage uniform_sky(double cd_m2) {
  study::FloatImage im(64, 64, {"R", "G", "B", "A"});
  const float v = static_cast<float>(cd_m2 / 179.0);  // luminance = 179 (0.265 R + 0.670 G + 0.065 B)
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double dx = x + 0.5 - 32, dy = y + 0.5 - 32;
      if (dx * dx + dy * dy > 32 * 32) continue;
      for (int c = 0; c < 3; ++c) im.at(static_cast<std::size_t>(c), x, y) = v;
      im.at(3, x, y) = 1;
    }
  return im;
}

/// Whether `letter` is drawn (2x) with its top-left at (x0, y0): every glyph pixel's block
/// matches.
bool letter_at(const study::RgbaImage& im, char letter, int x0, int y0) {
  for (int gy = 0; gy < GlyphHeight; ++gy)
    for (int gx = 0; gx < GlyphWidth; ++gx) {
      const auto& p = im.at(x0 + 2 * gx, y0 + 2 * gy);
      const bool set = p[3] == 255 && p[0] < 60;
      if (set != glyph_pixel(letter, gx, gy)) return false;
    }
  return true;
}

}  // namespace

TEST(SkyPicture, CompassLettersEastLeftAndColours) {
  const ColourScale scale{10, 1000, true, "luminance", "cd/m2"};
  const SkyPicture p = sky_picture(uniform_sky(100), scale);
  ASSERT_EQ(p.size, 64);
  const int m = p.letter_box, w = text_width_px("N", 2), h = text_height_px(2);
  const int cx = p.fisheye_x + 32, cy = p.fisheye_y + 32;
  EXPECT_TRUE(letter_at(p.image, 'N', cx - w / 2, (m - h) / 2));
  EXPECT_TRUE(letter_at(p.image, 'S', cx - w / 2, p.image.height - m + (m - h) / 2));
  EXPECT_TRUE(letter_at(p.image, 'E', (m - w) / 2, cy - h / 2));
  EXPECT_TRUE(letter_at(p.image, 'W', p.image.width - m + (m - w) / 2, cy - h / 2));
  EXPECT_FALSE(letter_at(p.image, 'W', (m - w) / 2, cy - h / 2));  // east is left
  // 100 cd/m2 is the middle of 10-1000 on a logarithmic scale.
  const auto mid = viridis(0.5);
  EXPECT_EQ(p.image.at(cx, cy), (std::array<std::uint8_t, 4>{mid[0], mid[1], mid[2], 255}));
  // The horizon circle: ink on the axes just outside the disc, none at the corners.
  EXPECT_LT(p.image.at(cx, p.fisheye_y - 1)[0], 60);
  EXPECT_EQ(p.image.at(p.fisheye_x, p.fisheye_y)[3], 0);
}

TEST(SkyPicture, LegendBarEndsAndTitle) {
  const ColourScale scale{10, 1000, true, "luminance", "cd/m2"};
  const study::FloatImage sky = uniform_sky(100);
  const study::RgbaImage png = sky_png(sky, scale, "annual mean, seen from below (east left)");
  const LegendImage layout = with_legend(sky_picture(sky, scale).image, scale, "Sky luminance, cd/m2",
                                         "annual mean, seen from below (east left)");
  ASSERT_EQ(png.width, layout.image.width);
  ASSERT_EQ(png.height, layout.image.height);
  const auto lo = viridis(0), hi = viridis(1);
  EXPECT_EQ(png.at(layout.bar_x, layout.bar_y + 3), (std::array<std::uint8_t, 4>{lo[0], lo[1], lo[2], 255}));
  EXPECT_EQ(png.at(layout.bar_x + layout.bar_width - 1, layout.bar_y + 3),
            (std::array<std::uint8_t, 4>{hi[0], hi[1], hi[2], 255}));
  // The title's first letter, S, just above the bar.
  const int title_y = layout.bar_y - GlyphLineHeight * LegendTextScale;
  EXPECT_TRUE(letter_at(png, 'S', LegendMarginPx, title_y));
}
