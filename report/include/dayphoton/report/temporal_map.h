// The temporal map of a grid: the grid's mean illuminance for every hour of the weather year,
// one column per day (in the file's order, 365 for an EPW year) and one row per clock hour
// (24), from the run's annual illuminance read through the results model's typed reader
// (study::read_illuminance_table, illuminance.bin). Each record goes to the slot of its clock
// hour, floor(mid-hour stamp) (the record 12:00-13:00, stamped 12.5, is hour 12); sub-hourly
// records of one slot are averaged. Written per grid and case as temporal_map.png beside the
// grid's other images: the map (2 pixels per day, 8 per hour, hour 0 at the bottom, below 1 lx
// dark grey, no record white), hour labels 0/6/12/18/24 on the left, month initials under the
// first day of each month, and the legend of the grid PNGs (image_legend.h): "Mean illuminance
// of the grid, lx" on the report's logarithmic 10-10 000 lx scale.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dayphoton/metrics/illuminance_table.h"
#include "dayphoton/report/colour_scale.h"
#include "dayphoton/study/image_files.h"
#include "dayphoton/study/results_model.h"

namespace dayphoton::report {

struct TemporalMap {
  std::vector<std::pair<int, int>> days;  ///< (month, day) per column
  std::vector<double> mean_lux;           ///< days x 24, [day * 24 + hour]; NaN: no record

  double at(int day, int hour) const { return mean_lux[static_cast<std::size_t>(day) * 24 + static_cast<std::size_t>(hour)]; }
};

/// Illuminance below which an hour counts as night (drawn dark grey).
inline constexpr double NightLux = 1.0;
inline constexpr std::array<std::uint8_t, 4> NightGrey{60, 60, 60, 255};
inline constexpr int TemporalPxPerDay = 2, TemporalPxPerHour = 8;

/// The map of a table: the mean over its sensors per record (over their areas when `area_m2`
/// is given, study::GridResult::area_m2), binned by day and clock hour.
TemporalMap temporal_map(const metrics::IlluminanceTable& table, const std::vector<double>& area_m2 = {});

/// The picture before the legend, and where pixel (day 0, hour 23) of the map starts.
struct TemporalPicture {
  study::RgbaImage image;
  int map_x = 0, map_y = 0;  ///< top-left of the map (hour 23 of day 0)
};
TemporalPicture temporal_picture(const TemporalMap& map, const ColourScale& scale);

/// temporal_picture with its legend.
study::RgbaImage temporal_png(const TemporalMap& map, const ColourScale& scale);

/// Write <grid folder>/temporal_map.png when the model says the grid has an illuminance table;
/// returns its path, or "" when it has none. InputError (located) for an unreadable table.
std::string write_temporal_map(const std::string& results_dir, const study::GridResult& grid);

}  // namespace dayphoton::report
