// report.html (report/report_html.h) from a synthetic results folder: a results model made with
// the run's builder (results_model_builder.h) and written as results.json, and value tables
// written with the study's own writers. Every section is present and listed for the page's
// self-check, every plot has drawn content, nothing is fetched from the network, values and
// pass/fail verdicts come from the model, names are escaped, variants and missing tables are
// handled, the text is deterministic, windows are the model's, and a folder without
// results.json (an older run) is an input error that says to run again. (The page is opened in
// a real browser by run_browser_test.sh.)
#include "dayphoton/report/report_html.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/results_model_builder.h"

using namespace dayphoton;
using namespace dayphoton::study;
using namespace dayphoton::report;
namespace fs = std::filesystem;

namespace {

std::string temp_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("dayphoton_report_html_test_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

std::vector<SensorPoint> grid_sensors() {
  std::vector<SensorPoint> sensors;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) sensors.push_back({{0.5 + i, 0.5 + j, 0.8}, {0, 0, 1}});
  return sensors;
}

/// A 4 x 3 grid at 0.8 m with DF, metrics and a year of hourly illuminance in `dir`.
void write_grid(const std::string& dir, bool with_metrics) {
  fs::create_directories(dir);
  const std::vector<SensorPoint> sensors = grid_sensors();
  std::vector<double> df;
  std::vector<metrics::SensorMetrics> m(sensors.size());
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    df.push_back(0.7 * static_cast<double>(i));
    m[i].da_percent = 8.0 * static_cast<double>(i);
    m[i].udi_original_percent = 50;
    m[i].udi_autonomous_percent = 40;
    m[i].mean_occupied_lux = 100.0 * static_cast<double>(i);
  }
  write_sensors_csv(sensors, dir + "/sensors.csv");
  write_daylight_factor_csv(sensors, df, dir + "/daylight_factor.csv");
  if (!with_metrics) return;
  write_metrics_csv(sensors, m, metrics::MetricSettings{}, {}, dir + "/metrics.csv");
  static const int days_in_month[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  std::vector<metrics::TimeStamp> steps;
  for (int month = 1; month <= 12; ++month)
    for (int day = 1; day <= days_in_month[month - 1]; ++day)
      for (int h = 0; h < 24; ++h) steps.push_back({month, day, h + 0.5});
  metrics::IlluminanceTable table(steps, sensors.size());
  for (std::size_t t = 0; t < steps.size(); ++t)
    for (std::size_t s = 0; s < sensors.size(); ++s)
      table.lux(t, s) = steps[t].hour > 6 && steps[t].hour < 18 ? static_cast<float>(50 * (s + 1) * steps[t].month) : 0.0f;
  write_illuminance_binary(table, dir + "/illuminance.bin");
}

/// The grid's model: its sensors, DF statistics and, with `annual`, the annual summary.
GridResult grid_model(const CaseResult& c, const std::string& folder, bool annual) {
  SensorGrid grid;
  grid.name = "north_wing";
  grid.points = grid_sensors();
  grid.planar = true;
  grid.outline = {{0, 0, 0.8}, {4, 0, 0.8}, {4, 3, 0.8}, {0, 3, 0.8}};
  GridResult g = results_grid(grid, folder, c, 0, 0);
  GridStatistics st;
  st.mean = 3.85;
  st.median = 3.85;
  st.max = 7.7;
  st.area_at_or_above_percent = {{2.0, 66.6667}};
  add_daylight_factor(g, st, DaylightFactorUncertainty{});
  if (!annual) return g;
  AnnualStudy study;
  study.sensors.resize(12);
  study.illuminance = metrics::IlluminanceTable(std::vector<metrics::TimeStamp>(8760), 12);
  study.occupied_hours = 3650;
  for (int i = 0; i < 7; ++i) study.sensors[static_cast<std::size_t>(i)].da_percent = 60;
  metrics::SensorMetrics& mean = study.grid.mean;
  mean.da_percent = 44;
  mean.cda_percent = 50;
  mean.da_max_percent = 1;
  mean.udi_below_percent = 20;
  mean.udi_original_percent = 50;
  mean.udi_above_original_percent = 30;
  mean.udi_supplementary_percent = 10;
  mean.udi_autonomous_percent = 40;
  mean.udi_above_revised_percent = 30;
  mean.mean_occupied_lux = 550;
  study.grid.sda_percent = 60;
  study.grid.ase_percent = 12.5;
  study.grid.en17037 = {{"minimum", 80.0, 100.0, true}, {"medium", 40.0, 80.0, false}};
  study.daylight_hours_source = "test";
  study.sky_description = "synthetic";
  add_annual(g, study, AnnualStudySettings{}, AnnualOutputs{true, true});
  return g;
}

/// A results folder: base grid with everything, one variant whose grid lacks metrics; a
/// south window in the base case only.
ResultsModel results_model(const std::string& dir) {
  ResultsModel m;
  m.project_name = "project.yaml";
  m.project_file = "/nonexistent/project.yaml";
  m.study = "annual";
  m.site_name = "Test <site> & co";
  m.latitude_deg = 51.5;
  m.longitude_deg = -0.12;
  m.weather_file = "/nonexistent/weather.epw";
  m.settings = {{"basis", "tregenza"}, {"photons per bin", "1000"}};
  m.notes = {"a note"};
  CaseResult base = results_case("base", "", "", {});
  base.openings = {{{1, 0, 1.0}, {3, 0, 1.0}, {3, 0, 2.0}, {1, 0, 2.0}}};
  base.grids.push_back(grid_model(base, "north_wing", true));
  CaseResult variant = results_case("variant", "tinted", "variants/tinted", {"window south removed"});
  variant.grids.push_back(grid_model(variant, "variants/tinted/north_wing", false));
  m.cases = {base, variant};
  write_grid(dir + "/north_wing", true);
  write_grid(dir + "/variants/tinted/north_wing", false);
  write_results_model(m, dir);
  return m;
}

std::string write_results(const std::string& name) {
  const std::string dir = temp_dir(name);
  results_model(dir);
  return dir;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(ReportHtml, EverySectionIsPresentListedAndDrawn) {
  const std::string dir = write_results("sections");
  const std::string html = report_html(dir);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, std::regex("data-sections=\"([^\"]*)\"")));
  const std::string listed = m[1];
  for (const std::string id :
       {"summary", "overview", "grid-north_wing", "grid-north_wing-df", "grid-north_wing-da", "grid-north_wing-udi",
        "grid-north_wing-compliance", "grid-north_wing-temporal", "grid-north_wing-histograms",
        "grid-north_wing-metrics", "grid-tinted--north_wing", "grid-tinted--north_wing-df"}) {
    EXPECT_NE(listed.find(id), std::string::npos) << id;
    EXPECT_EQ(count(html, "id=\"" + id + "\""), 1u) << id;
  }
  // Every plot has drawn elements. Base grid: DF, DA, UDI x 2 plans + legends, UDI bars,
  // temporal map + legend, 2 histograms; variant: DF plan + legend, DF histogram.
  std::size_t plots = 0;
  for (std::size_t at = html.find("<svg class=\"plot"); at != std::string::npos;
       at = html.find("<svg class=\"plot", at + 1), ++plots) {
    const std::string svg = html.substr(at, html.find("</svg>", at) - at);
    EXPECT_TRUE(svg.find("<rect") != std::string::npos || svg.find("<image") != std::string::npos) << svg.substr(0, 200);
  }
  EXPECT_EQ(plots, 4u * 2 + 1 + 2 + 2 + 2 + 1);
  EXPECT_EQ(count(html, "href=\"data:image/png;base64,"), 1u);  // the temporal map
  // The self-check script and its marker.
  EXPECT_NE(html.find("id=\"report-check\" data-status=\"pending\""), std::string::npos);
  EXPECT_NE(html.find("marker.setAttribute('data-status', 'ok')"), std::string::npos);
}

TEST(ReportHtml, IsSelfContained) {
  const std::string html = report_html(write_results("offline"));
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  EXPECT_EQ(html.find(" src="), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  // Every href is an in-page anchor or a data: URI.
  for (std::size_t at = html.find("href=\""); at != std::string::npos; at = html.find("href=\"", at + 1)) {
    const char c = html[at + 6];
    EXPECT_TRUE(c == '#' || html.compare(at + 6, 5, "data:") == 0) << html.substr(at, 40);
  }
}

TEST(ReportHtml, ValuesAndVerdictsComeFromTheModel) {
  const std::string dir = write_results("values");
  const std::string html = report_html(dir);
  EXPECT_NE(html.find("Test &lt;site&gt; &amp; co"), std::string::npos);
  EXPECT_EQ(html.find("Test <site>"), std::string::npos);
  EXPECT_NE(html.find("3.85 %"), std::string::npos);        // DF mean
  EXPECT_NE(html.find("66.6667 %"), std::string::npos);     // area with DF >= 2 %
  EXPECT_NE(html.find("60.0 % (7 of 12)"), std::string::npos);  // sDA
  // sDA 60 %: nominally accepted (>= 55 %) passes, preferred (>= 75 %) fails; ASE 12.5 % fails.
  const std::size_t compliance = html.find("id=\"grid-north_wing-compliance\"");
  const std::string part = html.substr(compliance, html.find("id=\"grid-north_wing-temporal\"") - compliance);
  const std::size_t nominal = part.find("nominally accepted"), preferred = part.find("75 % preferred"),
                    ase = part.find("12.5 %");
  ASSERT_NE(nominal, std::string::npos);
  ASSERT_NE(preferred, std::string::npos);
  ASSERT_NE(ase, std::string::npos);
  EXPECT_LT(part.find("badge pass", nominal), preferred);
  EXPECT_LT(part.find("badge fail", preferred), ase);
  EXPECT_NE(part.find("badge fail", ase), std::string::npos);
  EXPECT_NE(part.find(">minimum<"), std::string::npos);
  // The metric table's labels come from the typed thresholds (DA300, UDI 100-2000 lx).
  EXPECT_NE(html.find("daylight autonomy DA300: E &#8805; 300 lx</td><td class=\"n\">44.0"), std::string::npos);
  EXPECT_NE(html.find("UDI achieved (original): 100&#8211;2000 lx</td><td class=\"n\">50.0"), std::string::npos);
  // The variant's grid has no annual results and says so, without failing the report.
  const std::size_t variant = html.find("id=\"grid-tinted--north_wing\"");
  ASSERT_NE(variant, std::string::npos);
  EXPECT_NE(html.find("metrics.csv not found", variant), std::string::npos);
  EXPECT_NE(html.find("changes: window south removed", variant), std::string::npos);
  // The run's history is in its log (results.json holds no times).
  EXPECT_NE(html.find("<code>run.log</code>"), std::string::npos);
}

TEST(ReportHtml, DeterministicAndWrittenAtomically) {
  const std::string dir = write_results("deterministic");
  EXPECT_EQ(report_html(dir), report_html(dir));
  const std::string path = write_report(dir);
  EXPECT_EQ(path, dir + "/report.html");
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, report_html(dir));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos);
}

TEST(ReportHtml, WritesImagesForEveryGridAndVariant) {
  const std::string dir = write_results("images");
  const std::vector<std::string> written = write_images_and_report(dir);
  // Base grid: DF + 4 metrics x (EXR + PNG) and the temporal map of its illuminance table;
  // variant: DF x 2; no weather file: no sky; the report.
  EXPECT_EQ(written.size(), 10u + 1u + 2u + 1u);
  EXPECT_TRUE(fs::exists(dir + "/north_wing/temporal_map.png"));
  // The report links the picture in its temporal section (written after the images).
  EXPECT_NE(report_html(dir).find("<a href=\"north_wing/temporal_map.png\">"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/variants/tinted/north_wing/daylight_factor.exr"));
  EXPECT_TRUE(fs::exists(dir + "/north_wing/da300.png"));
  EXPECT_TRUE(fs::exists(dir + "/report.html"));
}

// Each case's plan shows the windows the model gives it: the base case's south window, none
// on the variant (which removed it).
TEST(ReportHtml, EachCaseShowsItsOwnWindows) {
  const std::string html = report_html(write_results("windows"));
  const std::size_t base_at = html.find("id=\"grid-north_wing\""), variant_at = html.find("id=\"grid-tinted--north_wing\"");
  ASSERT_NE(base_at, std::string::npos);
  ASSERT_NE(variant_at, std::string::npos);
  ASSERT_LT(base_at, variant_at);
  EXPECT_GE(count(html.substr(base_at, variant_at - base_at), "class=\"window\""), 1u);
  EXPECT_EQ(count(html.substr(variant_at), "class=\"window\""), 0u);
  EXPECT_EQ(html.substr(base_at, variant_at - base_at).find("changes:"), std::string::npos);
}

TEST(ReportHtml, FoldersFromTheModelCannotLeadOutOfTheResultsFolder) {
  // A hand-edited results.json names a grid folder outside the results folder.
  const std::string outside = temp_dir("outside");
  write_grid(outside + "/grid", false);
  const std::string dir = temp_dir("escape");
  ResultsModel m = results_model(dir);
  m.cases[0].grids[0].folder = "../dayphoton_report_html_test_outside/grid";
  write_results_model(m, dir);
  try {
    write_images_and_report(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a path of portable folder names"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(outside + "/grid/daylight_factor.exr"));
}

TEST(ReportHtml, AFolderWithoutResultsJsonIsAnInputErrorThatSaysToRunAgain) {
  const std::string dir = temp_dir("empty");
  try {
    report_html(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("results.json"), std::string::npos) << e.what();
  }
  // A results folder of an older dayphoton: summary.json but no results.json.
  std::ofstream(dir + "/summary.json") << R"({"grids": []})";
  try {
    write_images_and_report(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("older dayphoton; run the study again"), std::string::npos) << e.what();
  }
  std::ofstream(dir + "/results.json") << "[1, 2";
  EXPECT_THROW(report_html(dir), InputError);
}
