// What `dayphoton annual` takes from the run that wrote a results folder, read from its
// results model (results.json, study/results_model.h) and nothing else: the grid's metric
// settings (thresholds, occupancy plan), the site the sun was computed for and the ground
// reflectance. With them, `annual` on a results folder reproduces the run's metrics without
// the project file (docs/outputs.md, "results.json"; docs/cli.md).
#pragma once

#include <optional>
#include <string>

#include "dayphoton/core/source_location.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// How far above a grid folder results.json is looked for: DIR/<grid> (1 level) and
/// DIR/variants/<variant>/<grid> (3 levels).
constexpr int RecordedResultsMaxLevelsUp = 3;

/// A grid folder's place in the results model of its run.
struct RecordedGrid {
  std::string results_path;  ///< the results.json read
  ResultsModel model;
  /// The grid whose folder is the grid folder (relative to results.json's folder), if the
  /// model lists it; a case's grids are searched in the model's order.
  std::optional<GridResult> grid;
};

/// The results model of the run that wrote `grid_dir`: the first results.json found in the
/// folder's parent or above it (at most RecordedResultsMaxLevelsUp levels up). nullopt when
/// there is none (a folder copied out of its results). A results.json that does not read
/// (another schema version, a damaged file) is the reader's InputError.
std::optional<RecordedGrid> find_recorded_grid(const std::string& grid_dir);

/// The thresholds and occupancy plan the run used for `annual` (a grid's annual summary),
/// without a calendar (set it from the weather file). The plan's location is `where`, so a
/// plan that does not fit another weather file (an hourly schedule of another length) is an
/// InputError there. Throws InputError at `where` for a definition that does not make a plan
/// (an unknown kind, a weekday or daylight-saving name that does not parse).
AnnualStudySettings recorded_annual_settings(const AnnualSummary& annual, const SourceLocation& where);

/// The sun site the model records (`site.sun_site`, `site.sun_from_weather`), checked against
/// `weather`'s clock (recorded_sun_site); nullopt when the model records none (a
/// daylight-factor study).
std::optional<SunSite> recorded_sun_site(const ResultsModel& model, const std::string& results_path,
                                         const weather::HourlyWeather& weather);

}  // namespace dayphoton::study
