// The temporal map (report/temporal_map.h) of a year of hourly records on two sensors: 365 x 24
// slots, the record stamped 12.5 on 21 June (day 171) in hour 12 with the mean of its sensors,
// its pixel the scale's colour of that mean, nights dark grey, the month ticks under the first
// days, the legend's bar ends the scale's end colours; written from a results folder through the
// model's typed reader, which refuses a table of another sensor count.
#include "dayphoton/report/temporal_map.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/report/image_legend.h"
#include "dayphoton/study/annual_illuminance.h"
#include "../temp_folder.h"

using namespace dayphoton;
using namespace dayphoton::report;
namespace fs = std::filesystem;

namespace {

/// A non-leap year of hourly records (mid-hour stamps) on two sensors: 0 lx at night (before
/// 6:00, from 18:00), 50 lx by day, and 300 / 500 lx at 12:00-13:00 on 21 June.
metrics::IlluminanceTable year() {
  const int month_days[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  std::vector<metrics::TimeStamp> steps;
  for (int m = 1; m <= 12; ++m)
    for (int d = 1; d <= month_days[m - 1]; ++d)
      for (int h = 0; h < 24; ++h) steps.push_back({m, d, h + 0.5});
  metrics::IlluminanceTable table(steps, 2);
  for (std::size_t t = 0; t < steps.size(); ++t) {
    const auto& st = steps[t];
    const bool day = st.hour > 6 && st.hour < 18;
    for (std::size_t s = 0; s < 2; ++s) table.lux(t, s) = day ? 50.0f : 0.0f;
    if (st.month == 6 && st.day == 21 && st.hour == 12.5) {
      table.lux(t, 0) = 300;
      table.lux(t, 1) = 500;
    }
  }
  return table;
}

std::array<std::uint8_t, 4> rgba(const std::array<std::uint8_t, 3>& c) { return {c[0], c[1], c[2], 255}; }

}  // namespace

TEST(TemporalMap, DaysHoursAndAKnownHour) {
  const TemporalMap map = temporal_map(year());
  ASSERT_EQ(map.days.size(), 365u);
  ASSERT_EQ(map.mean_lux.size(), 365u * 24);
  EXPECT_EQ(map.days[171], std::make_pair(6, 21));
  EXPECT_DOUBLE_EQ(map.at(171, 12), 400);
  EXPECT_DOUBLE_EQ(map.at(171, 11), 50);
  EXPECT_DOUBLE_EQ(map.at(0, 2), 0);

  const ColourScale scale = illuminance_scale();
  const TemporalPicture p = temporal_picture(map, scale);
  EXPECT_EQ(p.image.width, p.map_x + 365 * TemporalPxPerDay + 8);
  EXPECT_GT(p.image.height, p.map_y + 24 * TemporalPxPerHour);
  const auto at = [&](int day, int hour, int dx, int dy) {
    return p.image.at(p.map_x + day * TemporalPxPerDay + dx, p.map_y + (23 - hour) * TemporalPxPerHour + dy);
  };
  for (int dy = 0; dy < TemporalPxPerHour; ++dy)
    for (int dx = 0; dx < TemporalPxPerDay; ++dx) {
      EXPECT_EQ(at(171, 12, dx, dy), rgba(scale.colour(400)));
      EXPECT_EQ(at(171, 13, dx, dy), rgba(scale.colour(50)));
      EXPECT_EQ(at(0, 2, dx, dy), NightGrey);
    }
  EXPECT_NE(scale.colour(400), scale.colour(50));
  // The tick under 1 February (day 31) and none under 2 February.
  const int below = p.map_y + 24 * TemporalPxPerHour + 2;
  EXPECT_EQ(p.image.at(p.map_x + 31 * TemporalPxPerDay, below)[3], 255);
  EXPECT_EQ(p.image.at(p.map_x + 32 * TemporalPxPerDay, below)[3], 0);

  // The legend below it: the bar from the colour of 10 lx to that of 10 000 lx.
  const study::RgbaImage png = temporal_png(map, scale);
  const LegendImage layout = with_legend(p.image, scale, "Mean illuminance of the grid, lx",
                                         "day of year across, hour of standard time up; below 1 lx grey");
  ASSERT_EQ(png.width, layout.image.width);
  ASSERT_EQ(png.height, layout.image.height);
  EXPECT_EQ(png.at(layout.bar_x, layout.bar_y + 2), rgba(viridis(0)));
  EXPECT_EQ(png.at(layout.bar_x + layout.bar_width - 1, layout.bar_y + 2), rgba(viridis(1)));
}

TEST(TemporalMap, WrittenFromTheResultsFolderThroughTheModel) {
  const fs::path root = test::process_temp_dir() / "dayphoton_temporal_map_test";
  fs::remove_all(root);
  fs::create_directories(root / "grid");
  study::write_illuminance_binary(year(), (root / "grid" / "illuminance.bin").string());
  study::GridResult grid;
  grid.name = "grid";
  grid.folder = "grid";
  grid.positions_m = {{0, 0, 0.8}, {1, 0, 0.8}};
  EXPECT_EQ(write_temporal_map(root.string(), grid), "");  // the model says there is none
  grid.has_illuminance_table = true;
  const std::string path = write_temporal_map(root.string(), grid);
  EXPECT_EQ(path, (root / "grid" / "temporal_map.png").string());
  EXPECT_TRUE(fs::exists(path));
  grid.positions_m.push_back({2, 0, 0.8});
  try {
    write_temporal_map(root.string(), grid);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("illuminance.bin"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("2 sensors, results.json has 3"), std::string::npos) << e.what();
  }
}
