// What a run reads and checks first: see run_inputs.h.
#include "dayphoton/study/run_inputs.h"

#include <cmath>
#include <cstdio>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/study/point_in_time.h"

namespace dayphoton::study {

std::optional<std::string> partial_year_message(const weather::HourlyWeather& weather, const std::string& path) {
  const std::size_t year_hours = (weather.leap_day_present ? 366u : 365u) * 24u;
  if (weather.records.empty() || weather.records.size() >= year_hours) return std::nullopt;
  const weather::WeatherRecord& first = weather.records.front();
  const weather::WeatherRecord& last = weather.records.back();
  return "the weather file " + path + " holds " + std::to_string(weather.records.size()) + " hourly records (" +
         std::to_string(first.month) + "/" + std::to_string(first.day) + " to " + std::to_string(last.month) + "/" +
         std::to_string(last.day) + "), not a whole year of " + std::to_string(year_hours) +
         ": the annual metrics count these records only, so ASE's hours above its limit per year and EN 17037's "
         "daylight hours (half the records) are not the standards' yearly quantities, and DA and sDA lack the "
         "missing days; use a whole-year file for compliance";
}

namespace {

/// A warning about the weather file, located at the project's `weather` key.
std::optional<Diagnostic> warning_at_weather_key(const project::Project& project,
                                                 const std::optional<std::string>& message) {
  if (!message) return std::nullopt;
  Diagnostic d;
  d.severity = Severity::Warning;
  d.location = project.weather.location;
  d.message = *message;
  return d;
}

}  // namespace

std::optional<Diagnostic> partial_year_warning(const project::Project& project, const weather::HourlyWeather& weather) {
  if (!project.outputs.metrics) return std::nullopt;
  return warning_at_weather_key(project, partial_year_message(weather, project.weather.path_as_written));
}

std::optional<std::string> radiation_clock_message(const weather::HourlyWeather& weather, const std::string& path) {
  const sky::RadiationTiming timing = sky::radiation_timing(weather, sky::solar_site_of(weather));
  if (!timing.measured || !(std::abs(timing.offset_h) >= RadiationClockWarning_h)) return std::nullopt;
  char offset[32];
  std::snprintf(offset, sizeof offset, "%.2f", std::abs(timing.offset_h));
  const double zone = weather.site.time_zone_h;
  char zone_text[32];
  std::snprintf(zone_text, sizeof zone_text, "UTC%s%g", zone < 0 ? "-" : "+", std::abs(zone));
  return "the radiation of the " + std::to_string(timing.days) + " clearest days of " + path + " is centred " +
         offset + " h " + (timing.offset_h < 0 ? "before" : "after") +
         " the sun's transit on the clock of its header (" + zone_text +
         "), where a clear day's light is centred on it: its records seem stamped on another clock (UTC, true "
         "solar time, daylight saving time, or shifted by a converter), so each hour's sun is traced about " +
         offset + " h away from where it stood when its light was measured, and the annual metrics move with it; put "
         "the records on the local standard time of the header's zone, or use a file whose records are";
}

std::optional<Diagnostic> radiation_clock_warning(const project::Project& project, const weather::HourlyWeather& weather) {
  if (project.study != project::StudyKind::Annual) return std::nullopt;
  return warning_at_weather_key(project, radiation_clock_message(weather, project.weather.path_as_written));
}

std::vector<Diagnostic> southern_daylight_saving_warnings(const project::Project& project, double sun_latitude_deg) {
  std::vector<Diagnostic> out;
  if (!(sun_latitude_deg < 0)) return out;
  char latitude[32];
  std::snprintf(latitude, sizeof latitude, "%.2f", sun_latitude_deg);
  auto check = [&](const project::OccupancySpec& o) {
    if (!o.given || o.daylight_saving == "none") return;
    Diagnostic d;
    d.severity = Severity::Warning;
    d.location = o.location;
    d.message = "daylight_saving: " + o.daylight_saving + " is a northern-hemisphere rule (clocks ahead from March to " +
                (o.daylight_saving == "eu" ? std::string("October") : std::string("November")) +
                "), winter at this site (latitude " + latitude + " deg); southern rules are not built in: give the occupied hours as a CSV schedule, or daylight_saving: none";
    out.push_back(std::move(d));
  };
  check(project.metrics.occupancy);
  for (const project::GridSpec& g : project.sensors.grids) check(g.occupancy);
  for (const project::PointsSpec& p : project.sensors.points) check(p.occupancy);
  return out;
}

RunInputs read_run_inputs(const project::Project& project) {
  RunInputs inputs;
  // The weather file and the site of its sun first: a time zone that is not the file's is an
  // input error.
  if (project.study == project::StudyKind::Annual) {
    inputs.weather = weather::read_hourly_weather(project.weather.path);
    inputs.sun_site = resolve_sun_site(project.site, *inputs.weather);
    inputs.below_horizon = annual_below_horizon_direct(*inputs.weather, *inputs.sun_site);
    if (std::optional<Diagnostic> w = partial_year_warning(project, *inputs.weather))
      inputs.weather->warnings.push_back(std::move(*w));
    if (std::optional<Diagnostic> w = radiation_clock_warning(project, *inputs.weather))
      inputs.weather->warnings.push_back(std::move(*w));
    for (Diagnostic& w : southern_daylight_saving_warnings(project, inputs.sun_site->solar.latitude_deg))
      inputs.weather->warnings.push_back(std::move(w));
  }
  // The points in time whose sun needs no tracing.
  check_points_in_time(project.points_in_time,
                       point_in_time_site(project, inputs.sun_site ? &*inputs.sun_site : nullptr));
  // Operated shading needs each hour's direct sun (the loader says so for project files).
  if (project.operation && project.simulation.sun != project::SunMode::Bins)
    throw InputError(project.operation->location, "operation needs the direct sun of every hour: set simulation.sun to 'bins'");
  return inputs;
}

}  // namespace dayphoton::study
