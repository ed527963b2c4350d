// `dayphoton sun WEATHER.epw|WEATHER.wea`: the sun position for every record of a weather
// file, at the record's mid-hour in local standard time, for the site of the file's header
// (EPW LOCATION, or the .wea header).
#include <cstdio>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/weather/hourly_weather.h"
#include "dayphoton/weather/site_clock.h"

namespace dayphoton::app {

sky::SolarPositionAlgorithm parse_solar_position(const std::string& name) {
  if (name == "spa") return sky::SolarPositionAlgorithm::Spa;
  if (name == "radiance") return sky::SolarPositionAlgorithm::Radiance;
  throw UsageError("unknown solar position algorithm '" + name + "' (spa or radiance)");
}

void require_written(std::ostream& out, const std::string& what) {
  out.flush();
  if (!out) throw std::runtime_error("could not write " + what + " to standard output");
}

int run_sun(const SunOptions& options, std::ostream& out) {
  const weather::HourlyWeather weather = weather::read_hourly_weather(options.weather_path);
  // What the reader accepted with a warning (ignored fields, filled gaps, header variants).
  for (const Diagnostic& w : weather.warnings) std::cerr << w.format();
  // Records stamped on another clock than the header's (docs/weather.md), as `check` says it.
  if (const std::optional<std::string> w =
          study::radiation_clock_message(weather, options.weather_path))
    std::cerr << "warning: " << *w << '\n';
  const weather::SiteClock clock = weather::SiteClock::for_weather(weather);
  const sky::SolarSite site = sky::solar_site_of(weather);
  sky::SolarPositionOptions solar;
  solar.algorithm = parse_solar_position(options.solar_position);
  solar.apply_refraction = solar.algorithm == sky::SolarPositionAlgorithm::Spa && !options.no_refraction;
  solar.radiance_series_has_leap_day = weather.leap_day_present;

  std::ostringstream table;
  table << "month,day,hour,altitude_deg,azimuth_deg,sun_up\n";
  char line[128];
  for (const weather::TimeStep& step : clock.steps(weather.records)) {
    const sky::SolarPosition p =
        sky::solar_position(site, sky::SolarTime{clock.year(), step.month, step.day, step.hour_lst}, solar);
    std::snprintf(line, sizeof line, "%d,%d,%.1f,%.4f,%.4f,%d\n", step.month, step.day, step.hour_lst,
                  rad_to_deg(p.altitude_rad), rad_to_deg(p.azimuth_rad), p.sun_up ? 1 : 0);
    table << line;
  }
  if (options.output_path.empty()) {
    out << table.str();
    require_written(out, "the sun table");
  }
  else write_file_atomically(options.output_path, table.str());
  return ExitOk;
}

}  // namespace dayphoton::app
