// The site of the sun: see sun_site.h.
#include "dayphoton/study/sun_site.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/study/annual_study.h"

namespace dayphoton::study {

namespace {

std::string fixed(double v, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

std::string latitude_text(double deg) { return fixed(std::abs(deg), 4) + (deg >= 0 ? " N" : " S"); }
std::string longitude_text(double deg) { return fixed(std::abs(deg), 4) + (deg >= 0 ? " E" : " W"); }
std::string utc_offset_text(double hours) { return std::string("UTC") + (hours >= 0 ? "+" : "") + format_number(hours); }

std::string station_of(const weather::HourlyWeather& weather) {
  const weather::WeatherSite& loc = weather.site;
  std::string name = loc.city;
  for (const std::string& part : {loc.state, loc.country})
    if (!part.empty() && part != "-") name += (name.empty() ? "" : ", ") + part;
  if (name.empty()) name = weather.source_name;
  return name + (loc.wmo.empty() ? std::string() : " (WMO " + loc.wmo + ")");
}

/// Distances in the messages: one decimal below 10 km, whole kilometres above.
std::string distance_text(double km) { return km < 10.0 ? fixed(km, 1) : fixed(km, 0); }

void set_distance(SunSite& s, const weather::HourlyWeather& weather) {
  const weather::WeatherSite& loc = weather.site;
  s.station = station_of(weather);
  s.station_distance_km =
      great_circle_distance_km(s.solar.latitude_deg, s.solar.longitude_deg, loc.latitude_deg, loc.longitude_east_deg);
}

/// The sun site at a given place and clock (not the header's), with the station's distance.
SunSite sun_site_at(double latitude_deg, double longitude_deg, double time_zone_h, double elevation_m,
                    const weather::HourlyWeather& weather) {
  SunSite s;
  s.solar.latitude_deg = latitude_deg;
  s.solar.longitude_deg = longitude_deg;
  s.solar.time_zone_h = time_zone_h;
  s.solar.elevation_m = elevation_m;
  set_distance(s, weather);
  return s;
}

std::string time_zone_problem(double site_h, const weather::HourlyWeather& weather) {
  const double file_h = weather.site.time_zone_h;
  return "the site's time zone (" + utc_offset_text(site_h) + ") is not the weather file's (" + utc_offset_text(file_h) +
         ", in the header of " + weather.source_name + "): its hours are local standard time of " +
         utc_offset_text(file_h) + " and each record's sun is computed at that instant; dayphoton does not move a "
         "year of records to another clock. Use a weather file of the site's time zone, or write time_zone: " +
         format_number(file_h) + " to read the hours (and the occupancy) on the station's clock, or "
         "from_weather: true for the station's site";
}

}  // namespace

double great_circle_distance_km(double latitude1_deg, double longitude1_deg, double latitude2_deg,
                                double longitude2_deg) {
  // Haversine formula (R. W. Sinnott, "Virtues of the Haversine", Sky and Telescope 68(2), 1984).
  const double p1 = deg_to_rad(latitude1_deg), p2 = deg_to_rad(latitude2_deg);
  const double dp = p2 - p1, dl = deg_to_rad(longitude2_deg - longitude1_deg);
  const double a = std::sin(dp / 2) * std::sin(dp / 2) + std::cos(p1) * std::cos(p2) * std::sin(dl / 2) * std::sin(dl / 2);
  return 2.0 * EarthMeanRadius_km * std::asin(std::min(1.0, std::sqrt(a)));
}

SunSite header_sun_site(const weather::HourlyWeather& weather) {
  SunSite s;
  s.solar = sky::solar_site_of(weather);
  s.from_weather = true;
  set_distance(s, weather);
  return s;
}

SunSite resolve_sun_site(const project::Site& site, const weather::HourlyWeather& weather) {
  if (site.from_weather) return header_sun_site(weather);
  if (site.time_zone_h != weather.site.time_zone_h)
    throw InputError(site.time_zone_location, time_zone_problem(site.time_zone_h, weather),
                     read_source_line(site.time_zone_location.file, site.time_zone_location.line));
  return sun_site_at(site.latitude_deg, site.longitude_deg, site.time_zone_h, site.elevation_m, weather);
}

std::string sun_site_sentence(const SunSite& s) {
  const std::string where = latitude_text(s.solar.latitude_deg) + ", " + longitude_text(s.solar.longitude_deg) +
                            ", " + utc_offset_text(s.solar.time_zone_h) + ", elevation " +
                            format_number(s.solar.elevation_m) + " m";
  if (s.from_weather)
    return "the sun is computed for the weather file's site (site: from_weather), as RADIANCE's gendaymtx does: " +
           s.station + ", " + where;
  return "the sun is computed for the project's site (" + where + ") with the irradiance of the weather station " +
         s.station + ", " + distance_text(s.station_distance_km) + " km away";
}

std::string station_distance_warning(const SunSite& s) {
  if (!(s.station_distance_km > StationDistanceWarning_km)) return "";
  return "warning: the weather station " + s.station + " is " + distance_text(s.station_distance_km) +
         " km from the site (more than " + format_number(StationDistanceWarning_km) +
         " km): the sun is the site's, the irradiance the station's, which stands for the site's sky only where the "
         "two climates are alike";
}

sky::BelowHorizonDirect annual_below_horizon_direct(const weather::HourlyWeather& weather, const SunSite& site) {
  return sky::below_horizon_direct(weather, site.solar, radiance_compatible_sky_options());
}

std::string below_horizon_note(const sky::BelowHorizonDirect& b, bool sun_bins) {
  if (b.records == 0)
    return "sun below the horizon: no hour of the weather file has direct irradiance while the sun is below the "
           "horizon at the sun's site";
  const double share = b.file_direct_normal_Wh_m2 > 0 ? 100.0 * b.direct_normal_Wh_m2 / b.file_direct_normal_Wh_m2 : 0.0;
  std::string text = "sun below the horizon: " + std::to_string(b.records) + (b.records == 1 ? " hour" : " hours") +
                     " of the weather file " + (b.records == 1 ? "has" : "have") +
                     " direct irradiance while the sun is below the horizon at the sun's site (" +
                     std::to_string(b.records_over_20_W_m2) + " above " + format_number(sky::GendaymtxBelowHorizonWarning_W_m2) +
                     " W/m2, largest " + format_number(b.largest_W_m2) +
                     " W/m2; " + fixed(b.direct_normal_Wh_m2 / 1000.0, 2) + " kWh/m2 of direct normal irradiation, " +
                     fixed(share, 2) + " % of the file's); ";
  text += sun_bins ? "their direct sun is left out (no sun below the horizon is traced), their sky is kept"
                   : "their sun is spread into the sky patches nearest to it, as gendaymtx does";
  return text;
}

std::optional<SunSite> recorded_sun_site(const std::string& summary_text, const std::string& summary_path,
                                         const weather::HourlyWeather& weather) {
  const nlohmann::json j = nlohmann::json::parse(summary_text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("site") || !j["site"].is_object()) return std::nullopt;
  const nlohmann::json& site = j["site"];
  if (!site.contains("from_weather") || !site["from_weather"].is_boolean()) return std::nullopt;
  if (site["from_weather"].get<bool>()) return header_sun_site(weather);
  for (const char* key : {"latitude_deg", "longitude_deg", "time_zone_h", "elevation_m"})
    if (!site.contains(key) || !site[key].is_number())
      throw InputError(SourceLocation{summary_path, 0, 0}, std::string("site.") + key + " is missing or not a number");
  project::Site p;
  p.latitude_deg = site["latitude_deg"].get<double>();
  p.longitude_deg = site["longitude_deg"].get<double>();
  p.time_zone_h = site["time_zone_h"].get<double>();
  p.elevation_m = site["elevation_m"].get<double>();
  return recorded_sun_site(p, summary_path, weather);
}

SunSite recorded_sun_site(const project::Site& p, const std::string& summary_path, const weather::HourlyWeather& weather) {
  if (p.from_weather) return header_sun_site(weather);
  if (!(std::abs(p.latitude_deg) <= 90 && std::abs(p.longitude_deg) <= 180 && std::abs(p.time_zone_h) <= 15 &&
        std::isfinite(p.elevation_m)))
    throw InputError(SourceLocation{summary_path, 0, 0}, "site: a latitude, longitude, time zone or elevation out of range");
  if (p.time_zone_h != weather.site.time_zone_h)
    throw InputError(SourceLocation{summary_path, 0, 0},
                     "the run computed the sun on the clock of " + utc_offset_text(p.time_zone_h) + ", but the records of " +
                         weather.source_name + " are local standard time of " +
                         utc_offset_text(weather.site.time_zone_h) +
                         ": give a weather file on the run's clock (of the run's site), or run the project with this "
                         "weather file");
  return sun_site_at(p.latitude_deg, p.longitude_deg, p.time_zone_h, p.elevation_m, weather);
}

SunSite recorded_or_header_sun_site(const std::string& summary_text, const std::string& summary_path,
                                    const weather::HourlyWeather& weather) {
  if (std::optional<SunSite> s = recorded_sun_site(summary_text, summary_path, weather)) return *s;
  return header_sun_site(weather);
}

}  // namespace dayphoton::study
