// The legend of the standalone false-colour PNGs; see image_legend.h.
#include "dayphoton/report/image_legend.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/report/bitmap_font.h"

namespace dayphoton::report {

namespace {

constexpr std::array<std::uint8_t, 4> White{255, 255, 255, 255};
constexpr std::array<std::uint8_t, 4> Ink{34, 34, 34, 255};
constexpr int BarHeightPx = 16, TickLengthPx = 5;

}  // namespace

LegendImage with_legend(const study::RgbaImage& plan, const ColourScale& scale, const std::string& title,
                        const std::string& note) {
  const int s = LegendTextScale, m = LegendMarginPx;
  const int line = GlyphLineHeight * s;
  const std::vector<double> ticks = scale.ticks();
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    std::string label = format_number(ticks[i]);
    if (i == 0 && scale.min > 0) label = "<=" + label;
    if (i + 1 == ticks.size()) label = ">=" + label;
    labels.push_back(label);
  }
  // Room for half of each end label beside the bar.
  const int end_room = std::max(text_width_px(labels.front(), s), text_width_px(labels.back(), s)) / 2;
  int width = plan.width + 2 * m;
  width = std::max(width, text_width_px(title, s) + 2 * m);
  width = std::max(width, text_width_px(note, s) + 2 * m);
  // Neighbouring labels never touch: the bar gives each tick interval the widest label plus a
  // gap (the ticks of a linear scale are evenly spaced, those of a logarithmic one by decades).
  int widest = 0;
  for (const std::string& label : labels) widest = std::max(widest, text_width_px(label, s));
  const int intervals = std::max<int>(1, static_cast<int>(ticks.size()) - 1);
  width = std::max(width, 2 * (m + end_room) + intervals * (widest + 2 * GlyphAdvance * s) + 1);

  LegendImage out;
  out.plan_x = m;
  out.plan_y = m;
  out.bar_x = m + end_room;
  out.bar_width = width - 2 * (m + end_room);
  out.bar_height = BarHeightPx;
  const int title_y = m + plan.height + m + 4;
  out.bar_y = title_y + line;
  const int labels_y = out.bar_y + BarHeightPx + TickLengthPx + 3;
  const int note_y = labels_y + line + 4;
  const int height = (note.empty() ? labels_y + line : note_y + line) + m - (GlyphLineHeight - GlyphHeight) * s;
  out.image = study::RgbaImage(width, height, White);
  study::RgbaImage& image = out.image;

  // The plan over white.
  for (int y = 0; y < plan.height; ++y)
    for (int x = 0; x < plan.width; ++x) {
      const auto& p = plan.at(x, y);
      auto& q = image.at(out.plan_x + x, out.plan_y + y);
      for (int c = 0; c < 3; ++c) q[c] = static_cast<std::uint8_t>((p[c] * p[3] + 255 * (255 - p[3]) + 127) / 255);
      q[3] = 255;
    }

  draw_text(image, m, title_y, title, s, Ink);
  // The bar: column i at position i / (width - 1) of the scale.
  for (int i = 0; i < out.bar_width; ++i) {
    const double t = out.bar_width > 1 ? static_cast<double>(i) / (out.bar_width - 1) : 0.0;
    const auto c = viridis(t);
    for (int y = 0; y < BarHeightPx; ++y) image.at(out.bar_x + i, out.bar_y + y) = {c[0], c[1], c[2], 255};
  }
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    const int x = out.bar_x + static_cast<int>(std::lround(scale.position(ticks[i]) * (out.bar_width - 1)));
    for (int y = 0; y < TickLengthPx; ++y) image.at(x, out.bar_y + BarHeightPx + y) = Ink;
    const int w = text_width_px(labels[i], s);
    const int left = std::clamp(x - w / 2, m, width - m - w);
    draw_text(image, left, labels_y, labels[i], s, Ink);
  }
  if (!note.empty()) draw_text(image, m, note_y, note, s, Ink);
  return out;
}

}  // namespace dayphoton::report
