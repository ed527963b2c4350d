// The appendix: site, weather station, simulation settings, versions, notes and where the
// run's timings are; see report_sections.h.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

#include <OpenEXRConfig.h>
#include <png.h>

#include "dayphoton/report/report_format.h"
#include "report_sections.h"

#ifndef DAYPHOTON_VERSION
#define DAYPHOTON_VERSION "unknown"
#endif

namespace dayphoton::report {

namespace {

using Rows = std::vector<std::pair<std::string, std::string>>;

/// Rows of (label, value), both already HTML.
std::string key_value_table(const Rows& rows) {
  std::ostringstream s;
  s << "<table class=\"kv\">";
  for (const auto& [k, v] : rows) s << "<tr><th>" << k << "</th><td>" << v << "</td></tr>";
  s << "</table>";
  return s.str();
}

/// The EPW LOCATION line (a weather file, not an output of the run) as label/value pairs;
/// empty if unreadable.
Rows weather_station(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return {};
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> f;
  std::stringstream ss(line);
  for (std::string s; std::getline(ss, s, ',');) f.push_back(s);
  if (f.size() < 10 || f[0] != "LOCATION") return {};
  return {{"station", esc(f[1] + (f[2].empty() || f[2] == "-" ? "" : ", " + f[2]) + ", " + f[3])},
          {"data source", esc(f[4])},
          {"WMO station number", esc(f[5])},
          {"station latitude (deg, north +)", esc(f[6])},
          {"station longitude (deg, east +)", esc(f[7])},
          {"time zone (h from UTC)", esc(f[8])},
          {"elevation (m)", esc(f[9])}};
}

std::string degrees(double v) { return format_value(v, Precision::Ratio); }

}  // namespace

std::string appendix_section(const study::ResultsModel& m) {
  std::ostringstream s;
  s << "<section id=\"appendix\"><h2>Appendix: site, weather, settings and versions</h2>";
  Rows site{{"project file", esc(m.project_name)},
            {"site", esc(m.site_name)},
            {"latitude (deg, north +)", degrees(m.latitude_deg)},
            {"longitude (deg, east +)", degrees(m.longitude_deg)},
            {"time zone (h from UTC, standard time)", format_value(m.time_zone_h, Precision::Length)},
            {"elevation (m)", format_value(m.elevation_m, Precision::Length)}};
  site.emplace_back("sun and sky", m.sun_site ? esc(m.sun_sentence) : std::string("daylight-factor study: no sun"));
  if (m.station_distance_km)
    site.emplace_back("weather station distance (km)", format_value(*m.station_distance_km, Precision::Area));
  if (m.below_horizon_hours)
    site.emplace_back("hours with direct irradiance and the sun below the horizon",
                      std::to_string(*m.below_horizon_hours) + " (their sun " + esc(m.below_horizon_their_sun) + ")");
  s << "<h3 id=\"site\">Site</h3>" << key_value_table(site);
  s << "<h3 id=\"weather\">Weather</h3>";
  Rows w;
  if (m.weather_file.empty()) {
    w.emplace_back("weather file", "none: a daylight-factor study (CIE overcast sky) needs no weather");
  } else {
    w.emplace_back("weather file", "<code>" + esc(std::filesystem::path(m.weather_file).filename().string()) + "</code>");
    for (const auto& row : weather_station(m.weather_file)) w.push_back(row);
    if (w.size() == 1) w.emplace_back("station", "the weather file is not readable from here");
  }
  s << key_value_table(w);
  s << "<h3 id=\"settings\">Simulation settings</h3>";
  Rows settings;
  for (const study::Setting& setting : m.settings) settings.emplace_back(esc(setting.name), esc(setting.value));
  s << key_value_table(settings);
  s << "<h3 id=\"run-time\">Run time</h3><p>The time of each step of the run, and which steps came from the cache "
       "instead of being computed, are in <code>run.log</code> in the results folder. The results model holds no "
       "times, so that a repeated run (computed or from the cache) gives the same results and the same report.</p>";
  s << "<h3 id=\"versions\">Versions</h3>";
  Rows versions{{"report written by", std::string("dayphoton ") + DAYPHOTON_VERSION},
                {"results computed by", "dayphoton " + esc(m.dayphoton_version) + " (" + esc(m.compiler) + ")"},
                {"OpenEXR", OPENEXR_VERSION_STRING},
                {"libpng", PNG_LIBPNG_VER_STRING}};
  s << key_value_table(versions);
  if (!m.notes.empty()) {
    s << "<h3 id=\"notes\">Notes of the run</h3><ul>";
    for (const std::string& n : m.notes) s << "<li>" << esc(n) << "</li>";
    s << "</ul>";
  }
  s << "</section>";
  return s.str();
}

}  // namespace dayphoton::report
