// The temporal map of a grid's mean illuminance; see temporal_map.h.
#include "dayphoton/report/temporal_map.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "dayphoton/report/bitmap_font.h"
#include "dayphoton/report/image_legend.h"

namespace dayphoton::report {

namespace {

constexpr std::array<std::uint8_t, 4> Ink{34, 34, 34, 255};
constexpr int TextScale = 2, MarginPx = 8, TickPx = 4;

}  // namespace

TemporalMap temporal_map(const metrics::IlluminanceTable& table, const std::vector<double>& area_m2) {
  TemporalMap map;
  std::vector<int> day_of_step(table.step_count());
  for (std::size_t t = 0; t < table.step_count(); ++t) {
    const auto& st = table.steps()[t];
    if (map.days.empty() || map.days.back() != std::make_pair(st.month, st.day)) map.days.emplace_back(st.month, st.day);
    day_of_step[t] = static_cast<int>(map.days.size()) - 1;
  }
  std::vector<double> sum(map.days.size() * 24, 0.0), count(sum.size(), 0.0);
  const bool weighted = area_m2.size() == table.sensor_count() && !area_m2.empty();
  double total_m2 = 0;
  for (double a : area_m2) total_m2 += a;
  for (std::size_t t = 0; t < table.step_count(); ++t) {
    double m = 0;
    if (weighted) {
      for (std::size_t s = 0; s < table.sensor_count(); ++s) m += area_m2[s] * table.lux(t, s);
      m = total_m2 > 0 ? m / total_m2 : 0;
    } else {
      for (std::size_t s = 0; s < table.sensor_count(); ++s) m += table.lux(t, s);
      if (table.sensor_count() > 0) m /= static_cast<double>(table.sensor_count());
    }
    const int slot = std::clamp(static_cast<int>(std::floor(table.steps()[t].hour)), 0, 23);
    const std::size_t i = static_cast<std::size_t>(day_of_step[t]) * 24 + static_cast<std::size_t>(slot);
    sum[i] += m;
    count[i] += 1;
  }
  map.mean_lux.assign(sum.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < sum.size(); ++i)
    if (count[i] > 0) map.mean_lux[i] = sum[i] / count[i];
  return map;
}

TemporalPicture temporal_picture(const TemporalMap& map, const ColourScale& scale) {
  TemporalPicture out;
  const int days = static_cast<int>(map.days.size());
  const int label_w = text_width_px("24", TextScale), text_h = text_height_px(TextScale);
  out.map_x = MarginPx + label_w + 6;
  out.map_y = MarginPx + text_h / 2;
  const int map_w = days * TemporalPxPerDay, map_h = 24 * TemporalPxPerHour;
  const int width = out.map_x + map_w + MarginPx;
  const int height = out.map_y + map_h + TickPx + 3 + text_h + MarginPx;
  out.image = study::RgbaImage(width, height);
  study::RgbaImage& im = out.image;
  for (int d = 0; d < days; ++d)
    for (int h = 0; h < 24; ++h) {
      const double v = map.at(d, h);
      if (std::isnan(v)) continue;
      std::array<std::uint8_t, 4> c = NightGrey;
      if (v >= NightLux) {
        const auto rgb = scale.colour(v);
        c = {rgb[0], rgb[1], rgb[2], 255};
      }
      for (int y = 0; y < TemporalPxPerHour; ++y)
        for (int x = 0; x < TemporalPxPerDay; ++x)
          im.at(out.map_x + d * TemporalPxPerDay + x, out.map_y + (23 - h) * TemporalPxPerHour + y) = c;
    }
  // Frame, hour labels at 0, 6, 12, 18, 24 (the bottom edge is hour 0), month initials.
  for (int x = out.map_x - 1; x <= out.map_x + map_w; ++x) {
    im.at(x, out.map_y - 1) = Ink;
    im.at(x, out.map_y + map_h) = Ink;
  }
  for (int y = out.map_y - 1; y <= out.map_y + map_h; ++y) {
    im.at(out.map_x - 1, y) = Ink;
    im.at(out.map_x + map_w, y) = Ink;
  }
  for (int h = 0; h <= 24; h += 6) {
    const std::string label = std::to_string(h);
    const int y = out.map_y + map_h - h * TemporalPxPerHour;
    draw_text(im, out.map_x - 4 - text_width_px(label, TextScale), std::clamp(y - text_h / 2, 0, height - text_h), label,
              TextScale, Ink);
  }
  static const char Initials[] = "JFMAMJJASOND";
  for (int d = 0; d < days; ++d) {
    const auto [month, day] = map.days[static_cast<std::size_t>(d)];
    if (day != 1 || month < 1 || month > 12) continue;
    const int x = out.map_x + d * TemporalPxPerDay;
    for (int y = 0; y < TickPx; ++y) im.at(x, out.map_y + map_h + 1 + y) = Ink;
    draw_text(im, x + 3, out.map_y + map_h + TickPx + 3, std::string(1, Initials[month - 1]), TextScale, Ink);
  }
  return out;
}

study::RgbaImage temporal_png(const TemporalMap& map, const ColourScale& scale) {
  return with_legend(temporal_picture(map, scale).image, scale, "Mean illuminance of the grid, lx",
                     "day of year across, hour of standard time up; below 1 lx grey")
      .image;
}

std::string write_temporal_map(const std::string& results_dir, const study::GridResult& grid) {
  if (!grid.has_illuminance_table) return {};
  const TemporalMap map = temporal_map(study::read_illuminance_table(results_dir, grid), grid.area_m2);
  if (map.days.empty()) return {};
  const std::string path = (std::filesystem::path(study::grid_folder(results_dir, grid)) / "temporal_map.png").string();
  study::write_png(temporal_png(map, illuminance_scale()), path);
  return path;
}

}  // namespace dayphoton::report
