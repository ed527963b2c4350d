// What a run reads and checks before it writes anything (study_runner.h): the weather file,
// the site of its sun, the hours with direct light below the horizon, the points in time and
// the operation's sun mode. `dayphoton run` reads them for every project of the command
// before the first one runs, so an input error of the last project is reported before
// anything is written (and, under mpirun, agreed on by the ranks and printed once).
#pragma once

#include <optional>

#include "dayphoton/project/project.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

struct RunInputs {
  std::optional<weather::HourlyWeather> weather;          ///< an annual study's weather file
  std::optional<SunSite> sun_site;                        ///< the site its sun is computed for
  std::optional<sky::BelowHorizonDirect> below_horizon;   ///< its direct light with the sun down
};

/// Reads and checks them. Throws InputError, located (file:line:column and key), for a weather
/// file that cannot be read or is on another clock than the site, a point in time that is not
/// in the year, or an operation without `sun: bins`.
RunInputs read_run_inputs(const project::Project& project);

}  // namespace dayphoton::study
