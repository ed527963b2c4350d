// The legend of the standalone PNGs (report/image_legend.h), its bitmap font
// (report/bitmap_font.h) and the outline of the sensor area (result_images.h).
#include "dayphoton/report/image_legend.h"

#include <gtest/gtest.h>

#include "dayphoton/report/bitmap_font.h"
#include "dayphoton/report/result_images.h"

using namespace dayphoton;
using namespace dayphoton::report;
using study::RgbaImage;

namespace {

bool same_rgb(const std::array<std::uint8_t, 4>& p, const std::array<std::uint8_t, 3>& c) {
  return p[0] == c[0] && p[1] == c[1] && p[2] == c[2] && p[3] == 255;
}

}  // namespace

TEST(BitmapFont, GlyphOneHasTheDotMatrixPattern) {
  const char* one[GlyphHeight] = {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."};
  for (int y = 0; y < GlyphHeight; ++y)
    for (int x = 0; x < GlyphWidth; ++x) EXPECT_EQ(glyph_pixel('1', x, y), one[y][x] == '#') << x << "," << y;
  EXPECT_FALSE(glyph_pixel('1', GlyphWidth, 0));
  // Characters without a glyph are drawn as '?'; lower case has its own glyphs ('m' for
  // metres is not 'M', mega).
  bool m_differs = false;
  for (int y = 0; y < GlyphHeight; ++y)
    for (int x = 0; x < GlyphWidth; ++x) {
      EXPECT_EQ(glyph_pixel('~', x, y), glyph_pixel('?', x, y));
      m_differs |= glyph_pixel('m', x, y) != glyph_pixel('M', x, y);
    }
  EXPECT_TRUE(m_differs);
  // Every character of the legends' texts has its own glyph (not the '?' fallback).
  for (char c : std::string("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz.,-()/%<>=:'")) {
    bool differs = false;
    for (int y = 0; y < GlyphHeight; ++y)
      for (int x = 0; x < GlyphWidth; ++x) differs |= glyph_pixel(c, x, y) != glyph_pixel('?', x, y);
    EXPECT_TRUE(differs) << c;
  }
}

TEST(BitmapFont, DrawTextScalesEachFontPixelToABlock) {
  RgbaImage image(40, 20);
  const std::array<std::uint8_t, 4> ink{1, 2, 3, 255};
  draw_text(image, 3, 2, "11", 2, ink);
  EXPECT_EQ(text_width_px("11", 2), 22);  // (2 x 6 - 1) font pixels
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 40; ++x) {
      const int fx = x - 3, fy = y - 2;
      bool set = false;
      if (fx >= 0 && fy >= 0 && fy < 2 * GlyphHeight) {
        const int glyph = fx / (2 * GlyphAdvance), gx = (fx % (2 * GlyphAdvance)) / 2;
        set = glyph < 2 && glyph_pixel('1', gx, fy / 2);
      }
      EXPECT_EQ(image.at(x, y) == ink, set) << x << "," << y;
    }
}

TEST(ImageLegend, BarEndsHaveTheScaleEndColoursAndThePlanSitsOnWhite) {
  RgbaImage plan(40, 30, {200, 10, 10, 255});
  plan.at(5, 5) = {0, 0, 0, 0};  // no sensor: white in the PNG
  const ColourScale scale = daylight_factor_scale();
  const LegendImage out = with_legend(plan, scale, "Daylight factor, %", "1 cell = 0.5 m");
  const RgbaImage& im = out.image;
  EXPECT_GT(im.width, plan.width);
  EXPECT_GT(im.height, plan.height + 2 * LegendMarginPx + 3 * GlyphLineHeight * LegendTextScale);
  EXPECT_GE(im.width, text_width_px("Daylight factor, %", LegendTextScale) + 2 * LegendMarginPx);
  EXPECT_TRUE(same_rgb(im.at(out.plan_x, out.plan_y), {200, 10, 10}));
  EXPECT_TRUE(same_rgb(im.at(out.plan_x + 5, out.plan_y + 5), {255, 255, 255}));
  EXPECT_TRUE(same_rgb(im.at(0, 0), {255, 255, 255}));
  ASSERT_GT(out.bar_width, 100);
  EXPECT_GE(out.bar_y, out.plan_y + plan.height);
  for (int y = out.bar_y; y < out.bar_y + out.bar_height; ++y) {
    EXPECT_TRUE(same_rgb(im.at(out.bar_x, y), viridis(0)));
    EXPECT_TRUE(same_rgb(im.at(out.bar_x + out.bar_width - 1, y), viridis(1)));
    EXPECT_TRUE(same_rgb(im.at(out.bar_x + (out.bar_width - 1) / 2, y), viridis(0.5)) ||
                same_rgb(im.at(out.bar_x + (out.bar_width - 1) / 2, y), viridis(0.5 - 1.0 / (out.bar_width - 1))));
  }
  EXPECT_EQ(viridis(0), (std::array<std::uint8_t, 3>{68, 1, 84}));
  // Tick marks under the bar at 0, 2, ..., 10 %: dark.
  for (double v : scale.ticks()) {
    const int x = out.bar_x + static_cast<int>(std::lround(scale.position(v) * (out.bar_width - 1)));
    EXPECT_LT(im.at(x, out.bar_y + out.bar_height + 1)[0], 60) << v;
  }
  // Text between the plan and the bar (the title) and below the bar (labels, note).
  int dark_above = 0, dark_below = 0;
  for (int y = out.plan_y + plan.height; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      if (im.at(x, y)[0] < 60 && im.at(x, y)[1] < 60) (y < out.bar_y ? dark_above : dark_below) += 1;
  EXPECT_GT(dark_above, 50);
  EXPECT_GT(dark_below, 50);
}

TEST(ImageLegend, OutlineFollowsTheCellsWithSensors) {
  // A 3 x 2 lattice without cell (2, 1), 4 px per cell.
  SensorLattice lattice;
  lattice.regular = true;
  lattice.columns = 3;
  lattice.rows = 2;
  lattice.spacing_m = 0.5;
  lattice.column_of = {0, 1, 2, 0, 1};
  lattice.row_of = {0, 0, 0, 1, 1};
  const ColourScale scale = percent_scale("daylight autonomy");
  RgbaImage image = false_colour_image(lattice, {50, 50, 50, 50, 50}, scale, 4);
  outline_sensor_cells(image, lattice, 4);
  const auto dark = [&](int x, int y) { return image.at(x, y)[0] == OutlineGrey && image.at(x, y)[3] == 255; };
  const auto fill = [&](int x, int y) { return same_rgb(image.at(x, y), scale.colour(50)); };
  EXPECT_TRUE(dark(0, 0));     // lattice corner
  EXPECT_TRUE(dark(11, 1));    // east edge of cell (2, 0)
  EXPECT_TRUE(dark(9, 3));     // south side of cell (2, 0): cell (2, 1) has no sensor
  EXPECT_TRUE(dark(7, 5));     // east side of cell (1, 1)
  EXPECT_TRUE(dark(5, 7));     // south edge of cell (1, 1)
  EXPECT_TRUE(fill(3, 1));     // between cells (0, 0) and (1, 0): no line
  EXPECT_TRUE(fill(5, 3));     // between cells (1, 0) and (1, 1): no line
  EXPECT_TRUE(fill(5, 5));     // inside
  EXPECT_EQ(image.at(9, 5)[3], 0);  // the hole stays transparent
  // Sensors not on a lattice: no outline.
  lattice.regular = false;
  RgbaImage row = false_colour_image(lattice, {50, 50, 50, 50, 50}, scale, 4);
  outline_sensor_cells(row, lattice, 4);
  EXPECT_TRUE(same_rgb(row.at(0, 0), scale.colour(50)));
}

TEST(ImageLegend, TitlesComeFromTheTypedQuantity) {
  study::SensorQuantity q;
  q.quantity = "daylight autonomy (300 lx)";
  q.unit = "%";
  q.scale = study::QuantityScale::Percent;
  EXPECT_EQ(legend_title(q), "Daylight autonomy (300 lx), % of occupied hours");
  q.quantity = "daylight factor";
  q.scale = study::QuantityScale::DaylightFactor;
  EXPECT_EQ(legend_title(q), "Daylight factor, %");
  q.quantity = "mean illuminance over the occupied hours";
  q.unit = "lx";
  q.scale = study::QuantityScale::Illuminance;
  EXPECT_EQ(legend_title(q), "Mean illuminance over the occupied hours, lx");
}
