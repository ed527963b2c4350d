// The site governs the sun (docs/sun.md, "The site of the sun"): the annual sky of a run is
// computed for the project's site with the weather station's irradiance, and
// `site: {from_weather: true}` keeps gendaymtx's behaviour (the weather file header's site).
//  - a site 10 degrees north of the station: the run's suns are NREL SPA's (and RADIANCE's
//    formulas') positions for that site, not the station's;
//  - the office as shipped (its site equal to the Oakland header) and the office with
//    from_weather: true give byte-identical annual results;
//  - the Mannheim site with the Oakland weather file: a located error at time_zone with
//    Mannheim's own zone; on the station's clock a different annual result, its hours with
//    direct light and the sun below the horizon counted in the log, summary.json and the
//    report, which say the same sentence about the sun's site;
//  - the cache keeps the sky of each site apart.
// Runs use the office at reduced photon counts (the sky, not the photons, is under test).
#include "dayphoton/report/report_html.h"
#include "dayphoton/study/cache_folder.h"
#include "dayphoton/study/run_inputs.h"
#include "dayphoton/study/sun_site.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../project/located_errors.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/solar_position.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "dayphoton/weather/site_clock.h"
#include "../temp_folder.h"
#include "../report/run_with_report.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const std::string OfficeYaml = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml";
const std::string OaklandEpw =
    std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The office project file with its `site:` section replaced by `site_lines` (each "  key: v").
std::string office_text_with_site(const std::string& site_lines) {
  const std::string text = read_text(OfficeYaml);
  const std::size_t begin = text.find("\nsite:\n");
  const std::size_t end = text.find("\nweather:", begin);
  EXPECT_NE(begin, std::string::npos);
  EXPECT_NE(end, std::string::npos);
  return text.substr(0, begin) + "\nsite:\n" + site_lines + "\n" + text.substr(end);
}

/// The office with that site, loaded as if it were projects/office/project.yaml (so the
/// weather path resolves), photon counts reduced for a quick run.
project::Project office_with_site(const std::string& site_lines) {
  project::LoadOptions options;
  options.output_folder_overridden = true;
  project::Project p = project::load_project_from_string(office_text_with_site(site_lines), OfficeYaml, options);
  p.simulation.photons_per_bin = 2000;
  p.simulation.direct_samples_per_bin = 16;
  p.outputs.images = false;
  return p;
}

const char* const OfficeSite =  // as projects/office/project.yaml writes it
    "  name: Oakland Metropolitan Arpt, CA, USA\n  latitude: 37.72\n  longitude: -122.22\n"
    "  time_zone: -8\n  elevation: 2\n  north: 0";
const char* const FromWeather = "  name: Oakland Metropolitan Arpt, CA, USA\n  from_weather: true\n  north: 0";
const char* const MannheimOnStationClock =
    "  name: Mannheim\n  latitude: 49.4875\n  longitude: 8.4660\n  time_zone: -8\n  elevation: 97";
const char* const MannheimOwnClock =
    "  name: Mannheim\n  latitude: 49.4875\n  longitude: 8.4660\n  time_zone: 1\n  elevation: 97";

/// Run `p` into `folder` (emptied first); if `cache_from` is given, its cache without the sky
/// artefacts is copied in first (photons and coefficients do not depend on the site), so the
/// run builds its own sky and reuses the rest.
void run_into(const project::Project& p, const fs::path& folder, const fs::path& cache_from = {},
              bool copy_sky = false) {
  const fs::path cache = default_cache_folder(folder.string());
  fs::remove_all(folder);
  fs::remove_all(cache);
  if (!cache_from.empty()) {
    fs::create_directories(cache);
    for (const auto& e : fs::directory_iterator(default_cache_folder(cache_from.string()))) {
      const std::string name = e.path().filename().string();
      const bool sky = name.rfind("sky-", 0) == 0 || name.rfind("suns-", 0) == 0;
      if ((!sky || copy_sky) && e.path().extension() == ".bin") fs::copy_file(e.path(), cache / name);
    }
  }
  test::run_with_report(p, folder);  // report.html, whose sentences are checked below
}

/// Text as report.html writes it (its five escaped characters; the sentences have only ').
std::string html_text(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '\'' ? std::string("&#39;") : std::string(1, c);
  return out;
}

nlohmann::json summary_of(const fs::path& folder) {
  return nlohmann::json::parse(read_text(folder / "summary.json"));
}

/// The files of a grid folder that hold results the sky enters (annual tables, metrics) and the DF.
const std::vector<std::string> ResultFiles = {"illuminance.bin", "metrics.csv",
                                              "grid_metrics.json", "daylight_factor.csv"};

/// The output folders of three runs of the office: as shipped, from_weather, and the Mannheim
/// site on the station's clock (each with the first run's photons, its own sky).
struct OfficeRuns {
  fs::path site_dir, from_weather_dir, mannheim_dir;
};

TEST(SunSite, TenDegreesNorthGivesTheSunPositionsSpaGivesThere) {
  const weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  const project::Project p = office_with_site(
      "  latitude: 47.72\n  longitude: -122.22\n  time_zone: -8\n  elevation: 2");  // Oakland + 10 deg
  const SunSite site = resolve_sun_site(p.site, epw);
  EXPECT_FALSE(site.from_weather);
  EXPECT_NEAR(site.station_distance_km, 10.0 * Pi / 180.0 * EarthMeanRadius_km, 0.01);
  const weather::SiteClock clock = weather::SiteClock::for_weather(epw);
  const std::vector<weather::TimeStep> steps = clock.steps(epw.records);
  const sky::SolarSite there{47.72, -122.22, -8, 2};
  const sky::SolarSite station = sky::solar_site_of(epw);

  // With SPA (Reda & Andreas 2004) and with the run's RADIANCE formulas: every sun of the
  // study is the position at the site, at the record's mid-hour.
  for (const sky::SolarPositionAlgorithm algorithm : {sky::SolarPositionAlgorithm::Spa, sky::SolarPositionAlgorithm::Radiance}) {
    sky::SkyMatrixOptions options = sun_excluded_sky_options(0.2);
    options.solar.algorithm = algorithm;
    const SkyAndSuns ss = annual_sky_and_suns(epw, site.solar, sky::PatchBasis::tregenza(), options);
    ASSERT_GT(ss.suns.size(), 3000u);
    sky::SolarPositionOptions solar = options.solar;
    solar.radiance_series_has_leap_day = epw.leap_day_present;
    double largest_error = 0, largest_change_deg = 0;
    for (const sky::SunRecord& s : ss.suns) {
      const weather::TimeStep& t = steps[s.step];
      const sky::SolarTime when{clock.year(), t.month, t.day, t.hour_lst};
      const Vec3 expected = sky::solar_position(there, when, solar).direction;
      largest_error = std::max(largest_error, length(s.direction - expected));
      const double at_station = sky::solar_position(station, when, solar).altitude_rad;
      largest_change_deg = std::max(largest_change_deg, std::abs(rad_to_deg(std::asin(s.direction.z) - at_station)));
    }
    EXPECT_LT(largest_error, 1e-6);  // float storage of the suns
    EXPECT_GT(largest_change_deg, 9.0);  // the station's suns would be 0 away
  }
  // At solar noon of the March equinox the altitude is 90 deg - latitude + declination: ten
  // degrees north lowers the noon sun by ten degrees (SPA, to its hour angle of a few deg).
  const sky::SolarPositionOptions spa;
  const sky::SolarTime noon{clock.year(), 3, 20, 12.5};
  const double here = rad_to_deg(sky::solar_position(there, noon, spa).altitude_rad);
  const double base = rad_to_deg(sky::solar_position(station, noon, spa).altitude_rad);
  EXPECT_NEAR(base - here, 10.0, 0.05);
}

/// The office as shipped (its site equal to the EPW header) and with from_weather: true.
void expect_site_equal_to_the_header_gives_the_results_of_from_weather(const OfficeRuns& r) {
  const fs::path &site_dir = r.site_dir, &from_weather_dir = r.from_weather_dir;
  for (const std::string& name : ResultFiles) {
    const fs::path a = site_dir / "workplane" / name, b = from_weather_dir / "workplane" / name;
    ASSERT_TRUE(fs::exists(a)) << a;
    EXPECT_EQ(read_text(a), read_text(b)) << name;
  }
  const nlohmann::json s = summary_of(site_dir), w = summary_of(from_weather_dir);
  EXPECT_FALSE(s["site"]["from_weather"].get<bool>());
  EXPECT_TRUE(w["site"]["from_weather"].get<bool>());
  for (const char* key : {"latitude_deg", "longitude_deg", "time_zone_h", "elevation_m"})
    EXPECT_EQ(s["site"][key], w["site"][key]) << key;
  EXPECT_NE(w["site"]["sun"].get<std::string>().find("the weather file's site (site: from_weather)"), std::string::npos);
}

/// The Mannheim site with the Oakland file (on its clock) against the Oakland site.
void expect_mannheim_with_the_oakland_file_is_not_the_oakland_result(const OfficeRuns& r) {
  const fs::path &site_dir = r.site_dir, &mannheim_dir = r.mannheim_dir;
  // The sun of Mannheim at Oakland's instants: the annual illuminance is another one.
  EXPECT_NE(read_text(site_dir / "workplane" / "illuminance.bin"), read_text(mannheim_dir / "workplane" / "illuminance.bin"));
  EXPECT_NE(read_text(site_dir / "workplane" / "metrics.csv"), read_text(mannheim_dir / "workplane" / "metrics.csv"));
  const nlohmann::json m = summary_of(mannheim_dir);
  EXPECT_NEAR(m["site"]["latitude_deg"].get<double>(), 49.4875, 1e-12);
  EXPECT_GT(m["site"]["station_distance_km"].get<double>(), 9000.0);
  bool warned = false;
  for (const nlohmann::json& n : m["notes"]) warned |= n.get<std::string>().find("warning: the weather station") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SunSite, AnotherTimeZoneThanTheWeatherFilesIsALocatedError) {
  const project::Project p = office_with_site(MannheimOwnClock);
  const fs::path folder = test::process_temp_dir() / "dayphoton_sun_site" / "mannheim_own_clock";
  fs::remove_all(folder);
  const std::vector<std::string> errors = project::test::located_errors([&] { run_into(p, folder); }, OfficeYaml);
  ASSERT_EQ(errors.size(), 1u);
  // Line and column of the value of time_zone in the rewritten file (the site's 5th line).
  const std::string text = office_text_with_site(MannheimOwnClock);
  const std::size_t at = text.find("time_zone: 1");
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  const std::string prefix = std::to_string(line) + ":14: the site's time zone (UTC+1) is not the weather file's (UTC-8";
  EXPECT_EQ(errors[0].substr(0, prefix.size()), prefix) << errors[0];
  EXPECT_NE(errors[0].find("time_zone: -8"), std::string::npos);
  EXPECT_NE(errors[0].find("from_weather: true"), std::string::npos);
  EXPECT_FALSE(fs::exists(folder / "summary.json"));
  EXPECT_FALSE(fs::exists(folder / "run.log"));  // nothing written before the error
}

// A weather file of part of a year (DATA PERIODS 3/1 to 12/31: 7344 records) gives annual
// metrics over its records only: ASE's hours per year and EN 17037's half year are then other
// quantities than the standards'. The run and `check` say so, located at the `weather` key;
// a whole year, or a project without metrics, gets no warning.
TEST(SunSite, APartOfAYearIsAWarningAtTheWeatherKey) {
  const project::Project p = office_with_site(OfficeSite);
  weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  EXPECT_FALSE(partial_year_warning(p, epw).has_value());
  epw.records.erase(epw.records.begin(), epw.records.begin() + (31 + 28) * 24);
  const std::optional<Diagnostic> w = partial_year_warning(p, epw);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->severity, Severity::Warning);
  EXPECT_EQ(w->location.line, p.weather.location.line);
  EXPECT_EQ(w->location.column, p.weather.location.column);
  EXPECT_NE(w->message.find("holds 7344 hourly records (3/1 to 12/31), not a whole year of 8760"), std::string::npos)
      << w->message;
  EXPECT_NE(w->message.find("ASE"), std::string::npos);
  EXPECT_NE(w->message.find("EN 17037"), std::string::npos);
  project::Project without_metrics = p;
  without_metrics.outputs.metrics = false;
  EXPECT_FALSE(partial_year_warning(without_metrics, epw).has_value());
}

// A weather file whose records are stamped on another clock than its header's (UTC data under
// a local zone, as PVGIS and ERA5 converters write it) reads without an error, yet every hour's
// sun is traced an hour from its light: on the office, Oakland's records moved by one hour
// gave DA300 4.1 points lower on average (up to 7.6) and UDI 100-2000 6.0 lower (docs/weather.md).
// The run and `check` warn, located at the `weather` key; the file as it is gets no warning,
// nor does a daylight-factor study, which reads no weather.
TEST(SunSite, RecordsOnAnotherClockThanTheHeadersAreAWarningAtTheWeatherKey) {
  const project::Project p = office_with_site(OfficeSite);
  const weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  EXPECT_FALSE(radiation_clock_warning(p, epw).has_value());
  weather::HourlyWeather utc = epw;  // each record takes the light of the next hour
  for (std::size_t t = 0; t + 1 < epw.records.size(); ++t) {
    utc.records[t].direct_normal_w_m2 = epw.records[t + 1].direct_normal_w_m2;
    utc.records[t].diffuse_horizontal_w_m2 = epw.records[t + 1].diffuse_horizontal_w_m2;
  }
  const std::optional<Diagnostic> w = radiation_clock_warning(p, utc);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->severity, Severity::Warning);
  EXPECT_EQ(w->location.line, p.weather.location.line);
  EXPECT_EQ(w->location.column, p.weather.location.column);
  EXPECT_NE(w->message.find("the radiation of the 71 clearest days of USA_CA_Oakland.Intl.AP.724930_TMY3.epw is "
                            "centred 1.0"),
            std::string::npos)
      << w->message;
  EXPECT_NE(w->message.find(" h before the sun's transit on the clock of its header (UTC-8)"), std::string::npos)
      << w->message;
  project::Project daylight_factor = p;
  daylight_factor.study = project::StudyKind::DaylightFactor;
  EXPECT_FALSE(radiation_clock_warning(daylight_factor, utc).has_value());
}

// The built-in DST rules are the northern hemisphere's: at a site south of the equator
// `daylight_saving: eu` would shift the occupied hours through the southern winter. A
// warning at the schedule's `occupancy` key (the project's and a grid's own); none in the
// north or without a rule.
TEST(SunSite, ANorthernDaylightSavingRuleSouthOfTheEquatorIsAWarning) {
  project::Project p = office_with_site(OfficeSite);
  EXPECT_TRUE(southern_daylight_saving_warnings(p, -33.87).empty());  // no schedule
  p.metrics.occupancy.given = true;
  p.metrics.occupancy.daylight_saving = "eu";
  p.metrics.occupancy.location = SourceLocation{"office.yaml", 40, 14};
  EXPECT_TRUE(southern_daylight_saving_warnings(p, 37.72).empty());
  ASSERT_FALSE(p.sensors.grids.empty());
  p.sensors.grids[0].occupancy.given = true;
  p.sensors.grids[0].occupancy.daylight_saving = "us";
  p.sensors.grids[0].occupancy.location = SourceLocation{"office.yaml", 52, 18};
  const std::vector<Diagnostic> w = southern_daylight_saving_warnings(p, -33.87);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0].location.line, 40);
  EXPECT_EQ(w[1].location.line, 52);
  EXPECT_NE(w[0].message.find("daylight_saving: eu is a northern-hemisphere rule (clocks ahead from March to October), "
                              "winter at this site (latitude -33.87 deg)"),
            std::string::npos)
      << w[0].message;
  EXPECT_NE(w[1].message.find("to November"), std::string::npos);
  p.metrics.occupancy.daylight_saving = "none";
  p.sensors.grids[0].occupancy.daylight_saving = "none";
  EXPECT_TRUE(southern_daylight_saving_warnings(p, -33.87).empty());
}

/// The hours with direct light and the sun below the horizon in the log, summary and report.
void expect_below_horizon_hours_counted_in_log_summary_and_report(const OfficeRuns& r) {
  const fs::path &site_dir = r.site_dir, &mannheim_dir = r.mannheim_dir;
  const weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  for (const auto& [folder, site_lines] : {std::pair{site_dir, OfficeSite}, std::pair{mannheim_dir, MannheimOnStationClock}}) {
    const SunSite site = resolve_sun_site(office_with_site(site_lines).site, epw);
    const sky::BelowHorizonDirect expected = annual_below_horizon_direct(epw, site);
    const nlohmann::json s = summary_of(folder);
    const nlohmann::json& b = s["site"]["below_horizon_direct"];
    EXPECT_EQ(b["hours"].get<std::size_t>(), expected.records);
    EXPECT_EQ(b["hours_over_20_W_m2"].get<std::size_t>(), expected.records_over_20_W_m2);
    EXPECT_DOUBLE_EQ(b["direct_normal_kWh_m2"].get<double>(), expected.direct_normal_Wh_m2 / 1000.0);
    EXPECT_EQ(b["their_sun"].get<std::string>(), "left out");  // the office traces sun bins
    // The same sentences in the log, the summary's notes and the report.
    const std::string note = below_horizon_note(expected, true);
    const std::string sentence = sun_site_sentence(site);
    EXPECT_EQ(s["site"]["sun"].get<std::string>(), sentence);
    const std::string log = read_text(folder / "run.log"), report = read_text(folder / "report.html");
    EXPECT_NE(log.find("\n" + note + "\n"), std::string::npos) << note;
    EXPECT_NE(log.find("site: " + sentence + "\n"), std::string::npos);
    bool in_notes = false;
    for (const nlohmann::json& n : s["notes"]) in_notes |= n.get<std::string>() == note;
    EXPECT_TRUE(in_notes);
    EXPECT_NE(report.find(html_text(note)), std::string::npos) << note;
    EXPECT_NE(report.find(html_text(sentence)), std::string::npos) << sentence;
  }
  // Oakland's own sun: a few sunrise and sunset hours (mid-hour sun just below the horizon);
  // Mannheim's sun at Oakland's instants: most of Oakland's direct light falls in its night.
  EXPECT_GT(summary_of(site_dir)["site"]["below_horizon_direct"]["hours"].get<std::size_t>(), 0u);
  EXPECT_GT(summary_of(mannheim_dir)["site"]["below_horizon_direct"]["hours"].get<std::size_t>(), 2000u);
}

/// `dayphoton annual` and the report's sky images read the site back from summary.json.
void expect_the_summary_records_the_site(const OfficeRuns& r) {
  const fs::path &from_weather_dir = r.from_weather_dir, &mannheim_dir = r.mannheim_dir;
  const weather::HourlyWeather epw = weather::read_hourly_weather(OaklandEpw);
  const std::string path = (mannheim_dir / "summary.json").string();
  const std::optional<SunSite> recorded = recorded_sun_site(read_text(mannheim_dir / "summary.json"), path, epw);
  ASSERT_TRUE(recorded.has_value());
  const SunSite expected = resolve_sun_site(office_with_site(MannheimOnStationClock).site, epw);
  EXPECT_EQ(recorded->solar.latitude_deg, expected.solar.latitude_deg);
  EXPECT_EQ(recorded->solar.longitude_deg, expected.solar.longitude_deg);
  EXPECT_EQ(recorded->solar.time_zone_h, expected.solar.time_zone_h);
  EXPECT_EQ(recorded->solar.elevation_m, expected.solar.elevation_m);
  EXPECT_FALSE(recorded->from_weather);
  const std::optional<SunSite> header =
      recorded_sun_site(read_text(from_weather_dir / "summary.json"), path, epw);
  ASSERT_TRUE(header.has_value());
  EXPECT_TRUE(header->from_weather);
  // A summary of an older run (no site.from_weather: its sky was the header's) or none.
  EXPECT_FALSE(recorded_sun_site(R"({"site": {"latitude_deg": 49.5, "longitude_deg": 8.5, "time_zone_h": 1}})", path, epw));
  EXPECT_FALSE(recorded_sun_site("", path, epw));
  EXPECT_TRUE(recorded_or_header_sun_site("", path, epw).from_weather);
  // Another weather file's clock than the run's: a located error naming the summary.
  const std::string other_clock =
      R"({"site": {"from_weather": false, "latitude_deg": 49.5, "longitude_deg": 8.5, "time_zone_h": 1, "elevation_m": 0}})";
  EXPECT_THROW(recorded_sun_site(other_clock, path, epw), InputError);
}

TEST(SunSite, OfficeRunsForItsSiteFromWeatherAndMannheim) {
  // One test for the three runs: CTest runs each test in a process of its own.
  const fs::path root = test::process_temp_dir() / "dayphoton_sun_site_runs";
  const OfficeRuns r{root / "site", root / "from_weather", root / "mannheim"};
  run_into(office_with_site(OfficeSite), r.site_dir);
  run_into(office_with_site(FromWeather), r.from_weather_dir, r.site_dir);
  // With the sky artefacts too: a key without the site would hand Mannheim Oakland's sky.
  run_into(office_with_site(MannheimOnStationClock), r.mannheim_dir, r.site_dir, true);
  {
    SCOPED_TRACE("site equal to the header vs from_weather");
    expect_site_equal_to_the_header_gives_the_results_of_from_weather(r);
  }
  {
    SCOPED_TRACE("Mannheim vs Oakland");
    expect_mannheim_with_the_oakland_file_is_not_the_oakland_result(r);
  }
  {
    SCOPED_TRACE("below-horizon hours");
    expect_below_horizon_hours_counted_in_log_summary_and_report(r);
  }
  {
    SCOPED_TRACE("the site recorded in summary.json");
    expect_the_summary_records_the_site(r);
  }
}

}  // namespace
}  // namespace dayphoton::study
