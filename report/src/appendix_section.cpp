// The appendix: site, weather station, simulation settings, the run's times, versions and
// notes; see report_sections.h.
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include <OpenEXRConfig.h>
#include <png.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/report/report_format.h"
#include "dayphoton/study/run_timings.h"
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

std::string seconds_cell(double s) { return "<td class=\"n\">" + esc(format_value(s, Precision::Seconds)) + " s</td>"; }

/// The run's times per step (timings.json): wall and CPU seconds, the work done, or "from
/// cache" for a step whose results the cache held; the time outside the steps and the total.
std::string run_time_block(const std::string& results_dir) {
  std::ostringstream s;
  s << "<h3 id=\"run-time\">Run time</h3>";
  std::optional<study::RunTimings> timings;
  try {
    timings = study::read_run_timings(results_dir);
  } catch (const std::exception& e) {
    s << "<p>The run's times could not be read: " << esc(e.what()) << "</p>";
    return s.str();
  }
  if (!timings) {
    s << "<p>This results folder has no <code>" << study::TimingsFileName
      << "</code> (it was written by a dayphoton that did not record the run's times): the time of each step, if "
         "any, is in <code>run.log</code>.</p>";
    return s.str();
  }
  double steps_wall = 0;
  std::size_t cached = 0;
  s << "<table class=\"timings\"><tr><th>step</th><th>time</th><th>CPU time</th><th>work</th></tr>";
  for (const study::StepTiming& st : timings->steps) {
    s << "<tr><td>" << esc(st.name) << "</td>";
    if (st.cached) {
      ++cached;
      s << "<td class=\"cached\" colspan=\"3\">from cache</td></tr>";
      continue;
    }
    steps_wall += st.wall_s;
    s << seconds_cell(st.wall_s) << seconds_cell(st.cpu_s) << "<td class=\"n\">" << st.work << ' ' << esc(st.unit)
      << "</td></tr>";
  }
  const double other = timings->total_wall_s - steps_wall;
  if (other >= 0.01)
    s << "<tr><td>between the steps (reading the project and the weather, daylight factors, writing the result files)</td>" << seconds_cell(other)
      << "<td></td><td></td></tr>";
  s << "<tr class=\"total\"><th>total, until the results were written</th>" << seconds_cell(timings->total_wall_s)
    << seconds_cell(timings->total_cpu_s) << "<td></td></tr></table>";
  s << "<p>Times of this run on " << timings->threads << (timings->threads == 1 ? " thread" : " threads")
    << " (CPU time: all threads of the process together)";
  if (cached > 0)
    s << "; " << cached << (cached == 1 ? " step" : " steps")
      << " took " << (cached == 1 ? "its" : "their") << " results from the cache of an earlier run and computed nothing";
  s << ". The images and this report were made after these times were recorded (<code>run.log</code> has their "
       "time). Times depend on the machine and its load, so they are kept out of the results "
       "(<code>results.json</code> and the tables), which a repeated run writes byte for byte.</p>";
  return s.str();
}

}  // namespace

std::string appendix_section(const study::ResultsModel& m, const std::string& results_dir) {
  std::ostringstream s;
  s << "<section id=\"appendix\"><h2>Appendix: site, weather, settings, run time and versions</h2>";
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
  s << run_time_block(results_dir);
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
