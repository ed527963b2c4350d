// The site the sun and the sky of a study are computed for (docs/sun.md, "The site of the
// sun"). A weather file brings two things: the irradiance measured at its station, and, in its
// header, the station's position and clock. The study takes the irradiance from the file and
// the sun from:
//  - the project's site (latitude, longitude, elevation): the default;
//  - the header's site with `site: {from_weather: true}`, as RADIANCE's gendaymtx does (for
//    comparisons with RADIANCE: the sky matrix is then gendaymtx's).
// Clock: an EPW record's hour is local standard time of the header's time zone, and its sun
// is computed at that instant (the record's mid-hour, weather/site_clock.h). A site time zone
// other than the station's would give the hours of a second clock: the occupancy, the hour
// columns of the tables and the operated-shading schedule all read the records' hours, so
// either every record would have to be moved to the site's clock (across midnight and the
// year's end) or the hours would be mislabelled. dayphoton does neither: it is a located error
// at `site.time_zone`, naming both zones and the ways out.
// Every place that says which site the sun is for (check, the run log, summary.json, the
// report) prints sun_site_sentence().
#pragma once

#include <optional>
#include <string>

#include "dayphoton/project/project.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/weather/hourly_weather.h"

namespace dayphoton::study {

/// A weather station farther than this from the site gets a warning (check, run log,
/// summary, report): its irradiance stands for the site's only where the climates are alike.
/// A policy of dayphoton, not a published limit; the sun itself is always the site's.
constexpr double StationDistanceWarning_km = 50.0;

/// Mean Earth radius (IUGG R1 = 6371.0088 km, Moritz, "Geodetic Reference System 1980",
/// Bulletin Geodesique 54, 1980), for the station's great-circle distance.
constexpr double EarthMeanRadius_km = 6371.0088;

struct SunSite {
  /// What the sun is computed for; time_zone_h is the weather file's clock (== the site's).
  sky::SolarSite solar;
  bool from_weather = false;  ///< solar is the weather file header's site
  std::string station;        ///< "Oakland Metropolitan Arpt, CA, USA (WMO 724930)"
  double station_distance_km = 0;  ///< great-circle distance from the site to the station
};

/// The site of the project's sun for this weather file. Throws InputError located at
/// site.time_zone when the project's time zone is not the file's (see the header comment).
SunSite resolve_sun_site(const project::Site& site, const weather::HourlyWeather& weather);

/// Great-circle distance (haversine on a sphere of EarthMeanRadius_km; within 0.5 % of the
/// ellipsoidal distance), km.
double great_circle_distance_km(double latitude1_deg, double longitude1_deg, double latitude2_deg,
                                double longitude2_deg);

/// "the sun is computed for the project's site (37.7200 N, 122.2200 W, UTC-8, elevation 2 m)
/// with the irradiance of the weather station Oakland ... (WMO 724930), 0.0 km away", or for
/// from_weather "... for the weather file's site (site: from_weather), as RADIANCE's
/// gendaymtx does: ...".
std::string sun_site_sentence(const SunSite& site);

/// "warning: the weather station is 9151 km from the site ..." when it is farther than
/// StationDistanceWarning_km; "" otherwise.
std::string station_distance_warning(const SunSite& site);

/// The hours of `weather` with direct normal irradiance > 0 while the sun is below the horizon
/// at the site, with the sun positions of the run's annual sky (RADIANCE's formulas,
/// radiance_compatible_sky_options): sky::below_horizon_direct.
sky::BelowHorizonDirect annual_below_horizon_direct(const weather::HourlyWeather& weather, const SunSite& site);

/// The run's line about those hours (always one line, also when there are none): how many,
/// how much light, and what the annual sky does with it: with the sun spread into patches
/// (`sun: spread`) their sun lands in the sky patches nearest to it, as gendaymtx does; with
/// sun bins (`sun_bins` true) their direct sun is left out.
std::string below_horizon_note(const sky::BelowHorizonDirect& below, bool sun_bins);

/// The sun site a run recorded in its summary.json (`site`, docs/outputs.md), to rebuild its
/// sky (`dayphoton annual`, the report's sky images). nullopt when the text is not such a
/// summary or predates the record (no `site.from_weather`; those runs used the weather
/// file header's site). InputError naming `summary_path` when the recorded time zone is not
/// `weather`'s (another weather file's clock).
std::optional<SunSite> recorded_sun_site(const std::string& summary_text, const std::string& summary_path,
                                         const weather::HourlyWeather& weather);

/// The same from a typed record (the results model's `site.sun_site`, `sun_from_weather`):
/// the header's site when `site.from_weather`, else the recorded position, checked as above
/// (InputError naming `path`).
SunSite recorded_sun_site(const project::Site& site, const std::string& path, const weather::HourlyWeather& weather);

/// The recorded sun site, or the header's (solar_site_of) when there is none.
SunSite recorded_or_header_sun_site(const std::string& summary_text, const std::string& summary_path,
                                    const weather::HourlyWeather& weather);

/// The header's site as a SunSite (from_weather: what gendaymtx and `dayphoton sky` use).
SunSite header_sun_site(const weather::HourlyWeather& weather);

}  // namespace dayphoton::study
