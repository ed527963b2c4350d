// What a run reads and checks before it writes anything (study_runner.h): the weather file,
// the site of its sun, the hours with direct light below the horizon, the points in time and
// the operation's sun mode. `dayphoton run` reads them for every project of the command
// before the first one runs, so an input error of the last project is reported before
// anything is written (and, under mpirun, agreed on by the ranks and printed once).
#pragma once

#include <optional>
#include <string>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/radiation_timing.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

struct RunInputs {
  std::optional<weather::HourlyWeather> weather;          ///< an annual study's weather file
  std::optional<SunSite> sun_site;                        ///< the site its sun is computed for
  std::optional<sky::BelowHorizonDirect> below_horizon;   ///< its direct light with the sun down
};

/// A weather file that does not hold a whole year (a DATA PERIODS line such as `3/1, 12/31`)
/// still gives every annual metric, but counted over its records only: LM-83's ASE counts
/// hours per year above 250 and EN 17037's daylight hours are half of a year's hours, so
/// both are then other quantities than the standards', and DA and sDA lack the missing
/// seasons. A warning located at the project's `weather` key, naming the file, the records
/// and the days it covers, when the project computes metrics; none for a whole year.
std::optional<Diagnostic> partial_year_warning(const project::Project& project, const weather::HourlyWeather& weather);
/// The text of that warning for the weather file as `path` names it (none for a whole year),
/// whatever computes the metrics: `dayphoton annual --weather FILE` prints it without a project.
std::optional<std::string> partial_year_message(const weather::HourlyWeather& weather, const std::string& path);

/// A weather file whose clearest days' radiation is centred this far or farther from the
/// sun's transit (sky::radiation_timing) gets a warning: its records seem stamped on another
/// clock than its header's. A policy of dayphoton: the files at hand are within 0.1 h
/// (Oakland TMY3), the clock errors met in practice are 0.5 h (half-hour stamps, daylight
/// saving time over half the year) to several hours (UTC); docs/weather.md.
constexpr double RadiationClockWarning_h = 0.5;

/// That warning, located at the project's `weather` key, for an annual study; none when the
/// offset is below RadiationClockWarning_h or cannot be measured. The offset is measured at
/// the station (the file's header), whatever the project's site: the question is whether the
/// file's records are on its own header's clock (a site far from the station has its own
/// warning, station_distance_warning).
std::optional<Diagnostic> radiation_clock_warning(const project::Project& project, const weather::HourlyWeather& weather);
/// Its text for the weather file as `path` names it, whatever reads it.
std::optional<std::string> radiation_clock_message(const weather::HourlyWeather& weather, const std::string& path);

/// The built-in daylight-saving rules (`daylight_saving: eu` or `us`) are the northern
/// hemisphere's: they set the clock ahead from March to October or November, which is winter
/// south of the equator, where a region that keeps DST does so from about October to April.
/// One warning per schedule that names such a rule at a site south of the equator
/// (`sun_latitude_deg` < 0), located at its `occupancy` key; southern rules are a CSV
/// schedule's business (docs/metrics.md).
std::vector<Diagnostic> southern_daylight_saving_warnings(const project::Project& project, double sun_latitude_deg);

/// Reads and checks them. Throws InputError, located (file:line:column and key), for a weather
/// file that cannot be read or is on another clock than the site, a point in time that is not
/// in the year, or an operation without `sun: bins`.
RunInputs read_run_inputs(const project::Project& project);

}  // namespace dayphoton::study
