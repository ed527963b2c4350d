// The sky fisheye PNG with compass letters and legend; see sky_picture.h.
#include "dayphoton/report/sky_picture.h"

#include <cmath>

#include "dayphoton/report/bitmap_font.h"
#include "dayphoton/report/image_legend.h"
#include "dayphoton/report/result_images.h"

namespace dayphoton::report {

namespace {

constexpr std::array<std::uint8_t, 4> Ink{34, 34, 34, 255};
constexpr int TextScale = 2;

}  // namespace

SkyPicture sky_picture(const study::FloatImage& rgb, const ColourScale& scale) {
  SkyPicture out;
  const study::RgbaImage fisheye = luminance_false_colour(rgb, scale);
  out.size = fisheye.width;
  out.letter_box = text_height_px(TextScale) + 10;
  out.fisheye_x = out.fisheye_y = out.letter_box;
  const int side = fisheye.width + 2 * out.letter_box;
  out.image = study::RgbaImage(side, fisheye.height + 2 * out.letter_box);
  study::RgbaImage& im = out.image;
  for (int y = 0; y < fisheye.height; ++y)
    for (int x = 0; x < fisheye.width; ++x) im.at(out.fisheye_x + x, out.fisheye_y + y) = fisheye.at(x, y);
  // The horizon: a 1-pixel circle just outside the fisheye's disc.
  const double cx = out.fisheye_x + 0.5 * fisheye.width, cy = out.fisheye_y + 0.5 * fisheye.height;
  const double r = 0.5 * fisheye.width + 0.5;
  const int steps = static_cast<int>(8 * r) + 8;
  for (int i = 0; i < steps; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / steps;
    const int x = static_cast<int>(std::floor(cx + r * std::cos(a))), y = static_cast<int>(std::floor(cy + r * std::sin(a)));
    if (x >= 0 && y >= 0 && x < im.width && y < im.height && im.at(x, y)[3] == 0) im.at(x, y) = Ink;
  }
  // The letters, centred in the margin on the axes (east left: seen from below).
  const int w = text_width_px("N", TextScale), h = text_height_px(TextScale), m = out.letter_box;
  const int mid_x = static_cast<int>(std::lround(cx)), mid_y = static_cast<int>(std::lround(cy));
  draw_text(im, mid_x - w / 2, (m - h) / 2, "N", TextScale, Ink);
  draw_text(im, mid_x - w / 2, im.height - m + (m - h) / 2, "S", TextScale, Ink);
  draw_text(im, (m - w) / 2, mid_y - h / 2, "E", TextScale, Ink);
  draw_text(im, im.width - m + (m - w) / 2, mid_y - h / 2, "W", TextScale, Ink);
  return out;
}

study::RgbaImage sky_png(const study::FloatImage& rgb, const ColourScale& scale, const std::string& note) {
  return with_legend(sky_picture(rgb, scale).image, scale, "Sky luminance, cd/m2", note).image;
}

}  // namespace dayphoton::report
