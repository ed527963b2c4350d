// Occupancy CSV files: one value per time step of the weather file, in file order, one per
// line; 1 = occupied, 0 = not (docs/metrics.md, "Occupancy schedules", says why fractions are
// refused). The first line may be a header (text that is not a number); blank lines and
// '#' comments are skipped; a line with several comma-separated fields is an error. Every
// problem is located "schedule.csv:LINE:COL".
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"

namespace dayphoton::project {

/// Policy: the most values a schedule may hold (a leap year of one-minute records); the
/// reader stops there instead of reading a huge file to its end.
constexpr std::size_t MaxOccupancyValues = 366 * 24 * 60;

/// The values of `path` (also the name in messages); problems go to `diag`.
std::vector<bool> read_occupancy_csv_text(const std::string& text, const std::string& path, Diagnostics& diag);

}  // namespace dayphoton::project
