// report.html (report/report_html.h) from a synthetic results folder: a results model made with
// the run's builder (results_model_builder.h) and written as results.json, and value tables
// written with the study's own writers. Every section is present and listed for the page's
// self-check, every plot has drawn content, nothing is fetched from the network, values and
// pass/fail verdicts come from the model, names are escaped, variants and missing tables are
// handled, the text is deterministic, windows and daylight systems are the model's (with a key),
// the run's times come from timings.json (cached steps "from cache", a folder without the file
// says so), and a folder without results.json (an older run) is an input error that says to
// run again. (The page is opened in
// a real browser by run_browser_test.sh.)
#include "dayphoton/report/report_html.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/report/report_format.h"
#include "dayphoton/report/validation_figures.h"
#include "dayphoton/study/compliance_verdicts.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/results_model_builder.h"
#include "dayphoton/study/run_timings.h"

using namespace dayphoton;
using namespace dayphoton::study;
using namespace dayphoton::report;
namespace fs = std::filesystem;

namespace {

/// A folder of this test process's own: CTest runs the tests of this file as separate
/// processes at once, and two of them writing one folder would see each other's files.
std::string temp_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() /
                     ("dayphoton_report_html_test_" + name + "_" + std::to_string(::getpid()));
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
  write_sensors_csv(sensors, {}, dir + "/sensors.csv");
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
  st.mean = annual ? 3.86 : 2.96;  // the variant: 0.9 points lower
  st.median = 3.24;
  st.min = 1.0;
  st.max = 7.7;
  st.uniformity = 0.26;
  st.area_at_or_above_percent = {{2.0, 66.6667}};
  DaylightFactorUncertainty u;
  u.rms_relative_stderr_percent = 1.234;
  u.max_relative_stderr_percent = 4.567;
  u.sensors_with_light = 12;
  add_daylight_factor(g, st, u);
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
  study.grid.ase_percent = 12.4;
  study.grid.en17037 = {{"minimum", 80.0, 100.0, true}, {"medium", 40.0, 80.0, false}};
  study.daylight_hours_source = "test";
  study.sky_description = "synthetic";
  add_annual(g, study, AnnualStudySettings{}, AnnualOutputs{true, true});
  return g;
}

/// The building of a case: a 4 m x 3 m x 3 m classroom with one 2 m x 1 m south window,
/// walls of reflectance 0.5 and glass of normal transmittance `glass` (as set_building makes it
/// from a project and its scene).
void add_building(CaseResult& c, double glass) {
  project::Project p;
  project::RoomSpec room;
  room.name = "classroom";
  room.size_m = {4, 3, 3};
  project::WindowSpec w;
  w.name = "south";
  w.wall = project::Wall::South;
  w.width_m = 2;
  w.height_m = 1;
  w.sill_m = 0.9;
  w.material = "glazing";
  room.windows = {w};
  p.geometry.rooms = {room};
  SceneDescription scene;
  MaterialSpec walls;
  walls.name = "walls";
  walls.reflectance = {0.5, 0.5, 0.5};
  MaterialSpec glazing;
  glazing.name = "glazing";
  glazing.type = MaterialType::Glass;
  glazing.transmittance = {glass, glass, glass};
  scene.materials = {walls, glazing};
  Surface wall;
  wall.material = 0;
  wall.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}};
  Surface pane;
  pane.material = 1;
  pane.port = true;
  pane.vertices = {{1, 0, 1}, {3, 0, 1}, {3, 0, 2}, {1, 0, 2}};
  scene.surfaces = {wall, pane};
  set_building(c, p, scene);
}

/// A grid on the east wall (vertical sensors) with daylight factors: no verdict applies.
GridResult wall_grid(const CaseResult& c) {
  SensorGrid grid;
  grid.name = "east_wall";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) grid.points.push_back({{4, 0.5 + i, 0.5 + j}, {-1, 0, 0}});
  grid.plane_normal = {-1, 0, 0};
  grid.outline = {{4, 0, 0}, {4, 3, 0}, {4, 3, 3}, {4, 0, 3}};
  grid.spacing_m = 1;
  GridResult g = results_grid(grid, "east_wall", c, 0, 0);
  GridStatistics st;
  st.mean = 1.5;
  st.median = 1.5;
  st.max = 3;
  add_daylight_factor(g, st, DaylightFactorUncertainty{});
  return g;
}

/// A results folder: base grid with everything and a wall grid, one variant (tinted glass)
/// whose grid lacks metrics; a south window in the base case only; the verdicts of
/// assess_compliance.
ResultsModel results_model(const std::string& dir) {
  ResultsModel m;
  m.project_name = "project.yaml";
  m.title = "Riverside <School>";
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
  base.grids.push_back(wall_grid(base));
  add_building(base, 0.6);
  CaseResult variant = results_case("variant", "tinted", "variants/tinted", {"window south removed"});
  variant.grids.push_back(grid_model(variant, "variants/tinted/north_wing", false));
  add_building(variant, 0.3);
  m.cases = {base, variant};
  assess_compliance(m);
  write_grid(dir + "/north_wing", true);
  write_grid(dir + "/variants/tinted/north_wing", false);
  {
    fs::create_directories(dir + "/east_wall");
    std::vector<SensorPoint> sensors;
    for (const Vec3& p : m.cases[0].grids[1].positions_m) sensors.push_back({p, {-1, 0, 0}});
    write_daylight_factor_csv(sensors, {1, 1.2, 1.4, 1.6, 1.8, 2}, dir + "/east_wall/daylight_factor.csv");
  }
  write_results_model(m, dir);
  return m;
}

std::string write_results(const std::string& name) {
  const std::string dir = temp_dir(name);
  results_model(dir);
  return dir;
}

/// One results folder and its report for the tests that only read the page (written once:
/// the year of hourly illuminance makes each folder take a tenth of a second).
const std::string& shared_report() {
  static const std::string html = report_html(write_results("shared"));
  return html;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The accuracy statements of a report: from their heading to the end of their list ("" if the
/// report has none).
std::string accuracy_statements(const std::string& html) {
  const std::size_t at = html.find("<h3 id=\"accuracy\">");
  return at == std::string::npos ? std::string() : html.substr(at, html.find("</ul>", at) - at);
}

/// The statement among `statements` with the data attributes `attrs` ("" if there is none).
std::string accuracy_item(const std::string& statements, const std::string& attrs) {
  const std::size_t i = statements.find("<li class=\"accuracy\" " + attrs + ">");
  return i == std::string::npos ? std::string() : statements.substr(i, statements.find("</li>", i) - i);
}

}  // namespace

TEST(ReportHtml, EverySectionIsPresentListedAndDrawn) {
  const std::string dir = write_results("sections");
  const std::string html = report_html(dir);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, std::regex("data-sections=\"([^\"]*)\"")));
  const std::string listed = " " + std::string(m[1]) + " ";
  for (const std::string id :
       {"summary", "verdicts", "building", "variants", "methods", "appendix", "grid-north_wing", "grid-north_wing-df",
        "grid-north_wing-da", "grid-north_wing-udi", "grid-north_wing-compliance", "grid-north_wing-temporal",
        "grid-north_wing-histograms", "grid-north_wing-metrics", "grid-east_wall", "grid-tinted--north_wing",
        "grid-tinted--north_wing-df"}) {
    EXPECT_NE(listed.find(" " + id + " "), std::string::npos) << id;
    EXPECT_EQ(count(html, "id=\"" + id + "\""), 1u) << id;
  }
  // Client order: summary first, settings last.
  const std::size_t summary = html.find("id=\"summary\""), verdicts = html.find("id=\"verdicts\""),
                    building = html.find("id=\"building\""), variants = html.find("id=\"variants\""),
                    grid = html.find("id=\"grid-north_wing\""), methods = html.find("id=\"methods\""),
                    appendix = html.find("id=\"appendix\"");
  EXPECT_LT(summary, verdicts);
  EXPECT_LT(verdicts, building);
  EXPECT_LT(building, variants);
  EXPECT_LT(variants, grid);
  EXPECT_LT(grid, methods);
  EXPECT_LT(methods, appendix);
  EXPECT_EQ(html.find("<section", appendix + 1), std::string::npos);  // nothing after the appendix
  // Every plot has drawn elements. Base grid: DF, DA, UDI x 2 plans + legends, UDI bars,
  // temporal map + legend, 2 histograms; wall grid and variant: DF plan + legend, DF histogram;
  // each plan's key (outline, windows, systems) beside its legend.
  std::size_t plots = 0;
  for (std::size_t at = html.find("<svg class=\"plot"); at != std::string::npos;
       at = html.find("<svg class=\"plot", at + 1), ++plots) {
    const std::string svg = html.substr(at, html.find("</svg>", at) - at);
    EXPECT_TRUE(svg.find("<rect") != std::string::npos || svg.find("<image") != std::string::npos) << svg.substr(0, 200);
  }
  EXPECT_EQ(plots, 4u * 2 + 1 + 2 + 2 + 3 + 3 + 6);
  EXPECT_EQ(count(html, "href=\"data:image/png;base64,"), 1u);  // the temporal map
  // The self-check script and its marker, hidden from readers (no developer line).
  EXPECT_NE(html.find("id=\"report-check\" data-status=\"pending\""), std::string::npos);
  EXPECT_NE(html.find("marker.setAttribute('data-status', 'ok')"), std::string::npos);
  EXPECT_NE(html.find("#report-check{display:none}"), std::string::npos);
  EXPECT_EQ(html.find("self-check:"), std::string::npos);
}

TEST(ReportHtml, TitleIsTheProjectsNameAndTheSummaryComesFirst) {
  const std::string& html = shared_report();
  EXPECT_NE(html.find("<title>Daylight report: Riverside &lt;School&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("<h1>Daylight report: Riverside &lt;School&gt;</h1>"), std::string::npos);
  EXPECT_EQ(html.find("<h1>Daylight report: Test"), std::string::npos);  // not the site or station
  // No file paths or results folder up front.
  const std::size_t summary = html.find("id=\"summary\"");
  EXPECT_EQ(html.substr(0, summary).find("/nonexistent"), std::string::npos);
  EXPECT_EQ(html.find("dayphoton_report_html_test_summary"), std::string::npos);
  const std::string part = html.substr(summary, html.find("id=\"verdicts\"") - summary);
  // Base row: mean DF 3.86 -> 3.9, median 3.24 -> 3.2, sDA 60, ASE 12.4 -> 12, UDI 50, EN 17037
  // minimum; LM-83 sDA pass, ASE fail, LEED 2 points, BREEAM pass (minimum DF 1.0 >= 0.8 %).
  const std::string base_row =
      "<td>base</td><td><a href=\"#grid-north_wing\">north_wing</a></td><td class=\"n\">12</td><td class=\"n\">3.9</td>"
      "<td class=\"n\">3.2</td><td class=\"n\">60</td><td class=\"n\">12</td><td class=\"n\">50</td><td>minimum</td>";
  const std::size_t row = part.find(base_row);
  ASSERT_NE(row, std::string::npos) << part.substr(0, 3000);
  const std::string cells = part.substr(row, part.find("</tr>", row) - row);
  EXPECT_EQ(count(cells, "badge pass\">pass<"), 2u) << cells;  // LM-83 sDA, BREEAM
  EXPECT_EQ(count(cells, "badge fail\">fail<"), 1u) << cells;  // LM-83 ASE
  EXPECT_NE(cells.find("badge pass\">2 points<"), std::string::npos) << cells;
  // The wall grid: marked vertical, no verdict, no EN 17037 level.
  const std::size_t wall = part.find("#grid-east_wall");
  ASSERT_NE(wall, std::string::npos);
  const std::string wall_cells = part.substr(wall, part.find("</tr>", wall) - wall);
  EXPECT_NE(wall_cells.find("(vertical)"), std::string::npos);
  EXPECT_EQ(wall_cells.find("badge pass"), std::string::npos) << wall_cells;
  EXPECT_EQ(wall_cells.find("badge fail"), std::string::npos) << wall_cells;
  EXPECT_EQ(count(wall_cells, ">n/a<"), 4u) << wall_cells;
  // What was not assessed, named.
  EXPECT_NE(part.find("id=\"not-assessed\""), std::string::npos);
  EXPECT_NE(part.find("EN 17037 view out, exposure to sunlight and protection from glare"), std::string::npos);
  EXPECT_NE(part.find("base / east_wall: LM-83, LEED, EN 17037 and BREEAM verdicts"), std::string::npos);
}

TEST(ReportHtml, VerdictsWithTheirRequirements) {
  const std::string& html = shared_report();
  const std::size_t at = html.find("id=\"verdicts\"");
  const std::string part = html.substr(at, html.find("id=\"building\"") - at);
  EXPECT_NE(part.find("<td>IES LM-83-12</td><td>sDA300/50%</td><td>&gt;= 55 % of the area (nominally accepted), "
                      "&gt;= 75 % preferred</td><td class=\"n\">60 %</td><td><span class=\"badge pass\">pass</span>"),
            std::string::npos)
      << part.substr(0, 2000);
  EXPECT_NE(part.find("<td>ASE1000,250</td><td>&lt;= 10 % of the area</td><td class=\"n\">12 %</td><td><span "
                      "class=\"badge fail\">fail</span></td><td>LEED v4.1: describe how the design addresses glare"),
            std::string::npos);
  EXPECT_NE(part.find("<td class=\"n\">1 of 3</td>"), std::string::npos);           // EN 17037 minimum
  EXPECT_NE(part.find("<td class=\"n\">3.9 %</td><td><span class=\"badge pass\">pass"), std::string::npos);  // BREEAM
  EXPECT_NE(part.find("the grid is vertical: these criteria are defined on horizontal work planes"), std::string::npos);
  // The grid's own compliance part shows the same verdicts and the EN 17037 levels.
  const std::size_t g = html.find("id=\"grid-north_wing-compliance\"");
  const std::string grid_part = html.substr(g, html.find("id=\"grid-north_wing-temporal\"") - g);
  EXPECT_NE(grid_part.find("nominally accepted"), std::string::npos);
  EXPECT_NE(grid_part.find(">minimum<"), std::string::npos);
  EXPECT_NE(grid_part.find("<td>80 %</td>"), std::string::npos);  // area reaching the minimum level's target
}

TEST(ReportHtml, BuildingMaterialsAndGridTables) {
  const std::string& html = shared_report();
  const std::size_t at = html.find("id=\"building\"");
  const std::string part = html.substr(at, html.find("id=\"variants\"") - at);
  // 4 x 3 x 3 m, floor 12 m2, window 2 m2, window-to-wall 2 / 12, glazing-to-floor 2 / 12.
  EXPECT_NE(part.find("<td>classroom</td><td class=\"n\">4 x 3 x 3</td><td class=\"n\">12</td><td class=\"n\">2</td>"
                      "<td class=\"n\">0</td><td class=\"n\">0.17</td><td class=\"n\">0.17</td>"),
            std::string::npos)
      << part.substr(0, 2000);
  EXPECT_NE(part.find("<td>classroom</td><td>south</td><td>south</td><td class=\"n\">2 x 1</td><td class=\"n\">0.9</td>"
                      "<td class=\"n\">2</td><td>glazing</td><td class=\"n\">1.00</td><td class=\"n\">1.00</td>"),
            std::string::npos);
  EXPECT_NE(part.find("<td>walls</td><td>lambertian</td><td class=\"n\">0.50</td><td class=\"n\">0.00</td>"
                      "<td class=\"n\">-</td><td class=\"n\">12</td>"),
            std::string::npos);
  EXPECT_NE(part.find("<td>glazing</td><td>glass</td><td class=\"n\">-</td><td class=\"n\">-</td>"
                      "<td class=\"n\">0.60</td><td class=\"n\">2</td>"),
            std::string::npos);
  // Grids: sensors, spacing, lattice, height; the wall grid vertical without a height.
  EXPECT_NE(part.find("<td>north_wing</td><td>horizontal</td><td class=\"n\">12</td><td class=\"n\">1</td>"
                      "<td class=\"n\">4 x 3</td><td class=\"n\">0.8</td>"),
            std::string::npos)
      << part.substr(part.find("id=\"grids\""));
  EXPECT_NE(part.find("<td>east_wall</td><td>vertical</td><td class=\"n\">6</td><td class=\"n\">1</td>"),
            std::string::npos);
}

TEST(ReportHtml, VariantsSideBySideWithDifferences) {
  const std::string& html = shared_report();
  const std::size_t at = html.find("id=\"variants\"");
  ASSERT_NE(at, std::string::npos);
  const std::string part = html.substr(at, html.find("id=\"grid-north_wing\"") - at);
  EXPECT_NE(part.find("<strong>tinted</strong>: window south removed"), std::string::npos);
  EXPECT_NE(part.find("<th>metric</th><th>base</th><th>tinted</th>"), std::string::npos);
  // Mean DF 3.86 -> 2.96: 3.9 and 3.0 (-0.90, 2 significant digits); the median is the same (0, no sign).
  EXPECT_NE(part.find("<td>mean daylight factor (%)</td><td class=\"n\">3.9</td><td class=\"n\">3.0 <span "
                      "class=\"delta\">(-0.90)</span></td>"),
            std::string::npos)
      << part;
  EXPECT_NE(part.find("<td>median daylight factor (%)</td><td class=\"n\">3.2</td><td class=\"n\">3.2 <span "
                      "class=\"delta\">(0)</span></td>"),
            std::string::npos);
  // The variant has no annual results: its sDA is "-", the base's shown.
  EXPECT_NE(part.find("<td>sDA (share of the area) (%)</td><td class=\"n\">60</td><td class=\"n\">-</td>"),
            std::string::npos);
  // Its glass differs from the base's.
  EXPECT_NE(part.find("<td>tinted</td><td>glazing</td><td>glass &#8594; glass</td><td class=\"n\">- &#8594; -</td>"
                      "<td class=\"n\">0.60 &#8594; 0.30</td>"),
            std::string::npos);
  // One case only: no variants section.
  const std::string dir = write_results("one_case");
  ResultsModel m = read_results_model(dir);
  m.cases.pop_back();
  EXPECT_EQ(report_html(dir, m).find("id=\"variants\""), std::string::npos);
}

TEST(ReportHtml, MethodsValidationAndUncertainty) {
  const std::string& html = shared_report();
  const std::size_t at = html.find("id=\"methods\"");
  const std::string part = html.substr(at, html.find("id=\"appendix\"") - at);
  EXPECT_NE(part.find("contribution photon map"), std::string::npos);
  EXPECT_NE(part.find("Perez all-weather sky model"), std::string::npos);
  EXPECT_NE(part.find("CIE standard overcast sky"), std::string::npos);
  EXPECT_NE(part.find("Tregenza basis"), std::string::npos);
  EXPECT_NE(part.find("Photons per sky patch: 1000"), std::string::npos);
  // Every validation figure, as declared once.
  for (const ValidationFigure& f : ValidationFigures) {
    EXPECT_NE(part.find("<td>" + esc(f.what) + "</td><td class=\"n\">" + f.doc_text + "</td>"),
              std::string::npos)
        << f.what;
  }
  // The uncertainty the run reached: RMS 1.234 -> 1.2 %, largest 4.567 -> 4.6 %, over 12 sensors.
  EXPECT_NE(part.find("<td>base</td><td>north_wing</td><td class=\"n\">12</td><td class=\"n\">1.2</td>"
                      "<td class=\"n\">4.6</td><td>photon counts given by the project</td>"),
            std::string::npos)
      << part.substr(part.find("id=\"uncertainty\""));
}

TEST(ReportHtml, ValidationFiguresAreTheOnesDocsValidationMdStates) {
  std::ifstream in(std::string(DAYPHOTON_SOURCE_DIR) + "/docs/validation.md");
  ASSERT_TRUE(in) << "docs/validation.md";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t begin = doc.find("<!-- office-validation:begin -->"), end = doc.find("<!-- office-validation:end -->");
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const std::string table = doc.substr(begin, end - begin);
  for (const ValidationFigure& f : ValidationFigures)
    EXPECT_NE(table.find("| " + std::string(f.doc_text)), std::string::npos) << f.doc_text;
  EXPECT_NE(doc.find("RADIANCE 5.4a"), std::string::npos);
}

TEST(ReportHtml, AppendixHoldsSettingsAndNoZeroTimes) {
  const std::string& html = shared_report();
  const std::size_t at = html.find("id=\"appendix\"");
  const std::string part = html.substr(at);
  EXPECT_NE(part.find("<tr><th>photons per bin</th><td>1000</td></tr>"), std::string::npos);
  // This folder has no timings.json (a run of a dayphoton before it): the appendix says so.
  EXPECT_NE(part.find("This results folder has no <code>timings.json</code>"), std::string::npos);
  EXPECT_NE(part.find("<code>run.log</code>"), std::string::npos);
  EXPECT_EQ(html.find("0.00 s"), std::string::npos);
  // Settings appear only in the appendix (and the methods' photons per patch).
  EXPECT_EQ(html.substr(0, at).find("<th>photons per bin</th>"), std::string::npos);
  EXPECT_NE(part.find("<code>weather.epw</code>"), std::string::npos);  // the file's name, not its path
}

// The run's times from timings.json: per step wall and CPU seconds at the report's precision
// and the work done; a cached step "from cache", never "0.00 s"; the time between the steps
// and the total. A malformed file is named in the report, which is still written.
TEST(ReportHtml, AppendixShowsTheRunsTimesWithCachedStepsFromCache) {
  const std::string dir = write_results("timings");
  RunTimings t;
  t.steps = {{"sky matrix", "hours", 0, 0, 0, true},
             {"photons", "sources", 146, 12.345, 23.4, false},
             {"coefficients north_wing", "sensors", 12, 0.004, 0.0031, false},
             {"annual north_wing", "hours", 8760, 1.234, 2.51, false}};
  t.total_wall_s = 20.0;
  t.total_cpu_s = 30.2;
  t.threads = 2;
  write_run_timings(t, dir);
  const std::string html = report_html(dir);
  const std::string part = html.substr(html.find("id=\"run-time\""));
  EXPECT_NE(part.find("<tr><td>sky matrix</td><td class=\"cached\" colspan=\"3\">from cache</td></tr>"),
            std::string::npos);
  EXPECT_NE(part.find("<tr><td>photons</td><td class=\"n\">12 s</td><td class=\"n\">23 s</td>"
                      "<td class=\"n\">146 sources</td></tr>"),
            std::string::npos);
  EXPECT_NE(part.find("<td>coefficients north_wing</td><td class=\"n\">&lt; 0.01 s</td>"), std::string::npos);
  EXPECT_NE(part.find("<td>annual north_wing</td><td class=\"n\">1.2 s</td><td class=\"n\">2.5 s</td>"),
            std::string::npos);
  // 20 - (12.345 + 0.004 + 1.234) = 6.417 s between the steps.
  EXPECT_NE(part.find("daylight factors, writing the result files)</td><td class=\"n\">6.4 s</td>"), std::string::npos);
  EXPECT_NE(part.find("<th>total, until the results were written</th><td class=\"n\">20 s</td><td class=\"n\">30 s</td>"),
            std::string::npos);
  EXPECT_NE(part.find("on 2 threads"), std::string::npos);
  EXPECT_NE(part.find("1 step took its results from the cache"), std::string::npos);
  EXPECT_EQ(html.find("0.00 s"), std::string::npos);
  EXPECT_EQ(part.find("has no <code>timings.json</code>"), std::string::npos);

  std::ofstream(dir + "/timings.json") << R"({"schema_version": 1, "threads": 2, "total_wall_s": "long",)"
                                          R"( "total_cpu_s": 1, "steps": []})";
  const std::string bad = report_html(dir);
  EXPECT_NE(bad.find("The run's times could not be read"), std::string::npos);
  EXPECT_NE(bad.find("&#39;total_wall_s&#39; is not a number of seconds"), std::string::npos);
  EXPECT_NE(bad.find("id=\"versions\""), std::string::npos);  // the rest of the appendix is there
  fs::remove_all(dir);
}

TEST(ReportHtml, PrintStylesBreakBetweenSectionsAndHideTheNavigation) {
  const std::string& html = shared_report();
  const std::size_t print = html.find("@media print{");
  ASSERT_NE(print, std::string::npos);
  const std::string css = html.substr(print, html.find("</style>") - print);
  EXPECT_NE(css.find("section{break-before:page;page-break-before:always}"), std::string::npos);
  EXPECT_NE(css.find("section#summary{break-before:auto"), std::string::npos);
  EXPECT_NE(css.find("nav,#report-check,.screen-only{display:none}"), std::string::npos);
  EXPECT_NE(css.find("break-inside:avoid"), std::string::npos);
  EXPECT_NE(html.find("<nav class=\"screen-only\">"), std::string::npos);
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
  EXPECT_NE(html.find("<tr><th>mean</th><td>3.9 %</td></tr>"), std::string::npos);        // DF mean, 0.1 %
  EXPECT_NE(html.find("<th>area with DF &#8805; 2.0 %</th><td>67 %</td>"), std::string::npos);  // whole points
  EXPECT_EQ(html.find("66.6667"), std::string::npos);  // no false precision
  // The metric table's labels come from the typed thresholds (DA300, UDI 100-2000 lx); values
  // in whole points, lux to 3 significant digits.
  EXPECT_NE(html.find("daylight autonomy DA300: E &#8805; 300 lx</td><td class=\"n\">44<"), std::string::npos);
  EXPECT_NE(html.find("UDI achieved (original): 100&#8211;2000 lx</td><td class=\"n\">50<"), std::string::npos);
  EXPECT_NE(html.find("mean illuminance, occupied hours</td><td class=\"n\">550<"), std::string::npos);
  // The variant's grid has no annual results and says so, without failing the report.
  const std::size_t variant = html.find("id=\"grid-tinted--north_wing\"");
  ASSERT_NE(variant, std::string::npos);
  EXPECT_NE(html.find("metrics.csv not found", variant), std::string::npos);
  EXPECT_NE(html.find("changes: window south removed", variant), std::string::npos);
}

TEST(ReportHtml, AGatheredGridsAccuracyIsExplainedByItsOwnGatherRounds) {
  // The work plane stopped the photon rounds on the photon budget; the gathered wall grid
  // then stopped its gather rounds on the ray limit. The wall's sentence must give its own
  // rays, gather rounds and stop, not the photon budget's; a gathered grid that met the target
  // gets no note about the case's stop.
  const std::string dir = temp_dir("accuracy_gather");
  ResultsModel m = results_model(dir);
  using Acc = DaylightFactorSummary::AccuracyReached;
  m.cases[0].grids[0].daylight_factor->accuracy =
      Acc{1.0, 1.4, 8, 33500000, "photon budget", "above target", 0, 0, "", 16};
  m.cases[0].grids[1].daylight_factor->accuracy =
      Acc{1.0, 1.9, 8, 33500000, "photon budget", "above target", 65536, 4, "gather ray limit", 16};
  m.cases[1].grids[0].daylight_factor->accuracy =
      Acc{1.0, 0.9, 2, 950000, "photon budget", "met", 4096, 2, "target met", 16};
  write_results_model(m, dir);
  const std::string html = report_html(dir);
  const std::string part = accuracy_statements(html);
  ASSERT_FALSE(part.empty());
  const std::string wall = accuracy_item(part, "data-part=\"sky\" data-case=\"base\" data-grid=\"east_wall\"");
  EXPECT_NE(wall.find("Reached 1.9 % by final gather at 65536 rays per sensor, after 4 gather rounds following 8 "
                      "rounds of photon tracing (33.5 million photons). <strong>Above the target.</strong> Why: this "
                      "grid's sensors are estimated by final gather (rays traced from each sensor), and the gather "
                      "rounds reached their limit of 65536 rays per sensor."),
            std::string::npos)
      << wall;
  EXPECT_EQ(wall.find("photon budget"), std::string::npos) << wall;
  EXPECT_EQ(wall.find("max_photons"), std::string::npos) << wall;
  // The work plane keeps the photon rounds' reason.
  const std::string plane = accuracy_item(part, "data-part=\"sky\" data-case=\"base\" data-grid=\"north_wing\"");
  EXPECT_NE(plane.find("Why: the photon budget was reached first."), std::string::npos) << plane;
  const std::string met = accuracy_item(part, "data-part=\"sky\" data-case=\"tinted\" data-grid=\"north_wing\"");
  EXPECT_NE(met.find("Reached 0.90 % by final gather at 4096 rays per sensor, after 2 gather rounds following 2 "
                     "rounds of photon tracing (950 000 photons). Target met."),
            std::string::npos)
      << met;
  EXPECT_EQ(met.find("stopped with"), std::string::npos) << met;
}

namespace {

/// The words of a direct-rays-limit stop: `who` ("the rounds", "the gather rounds") and the
/// grid's shadow rays per sky patch at the end, `samples`, at or above the rounds' limit.
std::string direct_rays_limit_words(const std::string& who, int samples) {
  return "those rays were at their limit, " + std::to_string(samples) + " per sky patch for this grid: " + who +
         " raise them up to " + std::to_string(MaxDirectSamplesPerBin) +
         " per sky patch, and keep the project's own <code>simulation.direct_samples_per_bin</code> where it is "
         "higher. What to do: set <code>simulation.direct_samples_per_bin</code> above " + std::to_string(samples) +
         ", or ask for a looser target.";
}

}  // namespace

TEST(ReportHtml, TheDirectRaysLimitNamesTheKeyToChange) {
  // The shadow rays were at the rounds' limit and the rounds stopped there: the sentence says
  // so with the grid's own count from results.json (the rounds' limit, or the project's own
  // larger count the rounds keep), advises a count above it, and names direct_samples_per_bin
  // (not the photon keys).
  for (const int samples : {MaxDirectSamplesPerBin, 2 * MaxDirectSamplesPerBin}) {
    const std::string dir = temp_dir("accuracy_direct_limit_" + std::to_string(samples));
    ResultsModel m = results_model(dir);
    using Acc = DaylightFactorSummary::AccuracyReached;
    m.cases[0].grids[0].daylight_factor->accuracy =
        Acc{1.0, 1.3, 3, 4000000, "direct rays limit", "above target", 0, 0, "", samples};
    write_results_model(m, dir);
    const std::string html = report_html(dir);
    const std::size_t at = html.find("data-part=\"sky\" data-case=\"base\" data-grid=\"north_wing\"");
    ASSERT_NE(at, std::string::npos);
    const std::string item = html.substr(at, html.find("</li>", at) - at);
    EXPECT_NE(item.find("<strong>Above the target.</strong> Why: the sensors still above the target are so by the "
                        "noise of their direct light (the shadow rays toward the sky through the openings), and " +
                        direct_rays_limit_words("the rounds", samples)),
              std::string::npos)
        << item;
    EXPECT_EQ(item.find("raised those rays"), std::string::npos) << item;
    EXPECT_EQ(item.find("max_photons"), std::string::npos) << item;
  }
}

TEST(ReportHtml, AGatheredGridsDirectRaysLimitNamesTheKeyToChange) {
  // A grid estimated by final gather whose gather rounds stopped with its shadow rays at their limit:
  // its own sentence says so and names direct_samples_per_bin, not the gather or photon keys.
  const std::string dir = temp_dir("accuracy_gather_direct_limit");
  ResultsModel m = results_model(dir);
  using Acc = DaylightFactorSummary::AccuracyReached;
  m.cases[0].grids[1].daylight_factor->accuracy =
      Acc{1.0, 1.4, 3, 4000000, "direct rays limit", "above target", 4096, 4, "direct rays limit",
          MaxDirectSamplesPerBin};
  write_results_model(m, dir);
  const std::string html = report_html(dir);
  const std::string wall =
      accuracy_item(accuracy_statements(html), "data-part=\"sky\" data-case=\"base\" data-grid=\"east_wall\"");
  ASSERT_FALSE(wall.empty()) << html;
  EXPECT_NE(wall.find("estimated by final gather"), std::string::npos) << wall;
  EXPECT_NE(wall.find(direct_rays_limit_words("the gather rounds", MaxDirectSamplesPerBin)), std::string::npos)
      << wall;
  EXPECT_EQ(wall.find("raised those rays"), std::string::npos) << wall;
  EXPECT_EQ(wall.find("stopped with"), std::string::npos) << wall;
  EXPECT_EQ(wall.find("gather_rays"), std::string::npos) << wall;
}

TEST(ReportHtml, AGatheredGridsPhotonPartStopNamesTheBudgetOrLimit) {
  // Gathered grids whose photon part (what more gather rays do not reduce) kept them above the
  // target and the photon budget, or the photon rounds' limit, left no room for more photons:
  // each sentence names that stop and the key to change, and does not claim photon rounds were
  // traced for the grid (the budget may have refused its first request).
  const std::string dir = temp_dir("accuracy_gather_photons");
  ResultsModel m = results_model(dir);
  using Acc = DaylightFactorSummary::AccuracyReached;
  m.cases[0].grids[1].daylight_factor->accuracy =
      Acc{1.0, 1.6, 5, 33500000, "photon budget", "above target", 16384, 7, "photon budget", 16};
  m.cases[1].grids[0].daylight_factor->accuracy =
      Acc{1.0, 1.2, 8, 12000000, "photon round limit", "above target", 4096, 9, "photon round limit", 16};
  write_results_model(m, dir);
  const std::string html = report_html(dir);
  const std::string part = accuracy_statements(html);
  ASSERT_FALSE(part.empty());
  const std::string wall = accuracy_item(part, "data-part=\"sky\" data-case=\"base\" data-grid=\"east_wall\"");
  EXPECT_NE(wall.find("more photons would, but the photon budget left no room for them. What to do: raise "
                      "<code>simulation.accuracy.max_photons</code>"),
            std::string::npos)
      << wall;
  EXPECT_EQ(wall.find("traced more photons for it"), std::string::npos) << wall;
  const std::string limit = accuracy_item(part, "data-part=\"sky\" data-case=\"tinted\" data-grid=\"north_wing\"");
  EXPECT_NE(limit.find("more photons would, but the photon rounds had reached their limit of " +
                       std::to_string(study::MaxAccuracyRounds) + " rounds."),
            std::string::npos)
      << limit;
  EXPECT_EQ(limit.find("traced more photons for it"), std::string::npos) << limit;
}

TEST(ReportHtml, SensorsNextToACutStateWhatTheyReachedBesideTheVerdict) {
  // A work plane whose 12 sensors next to a column are gathered and left out of the measure:
  // above the target, the verdict says the target is met by the sensors it measures only and
  // names those sensors' largest error and the key; within it, it says so.
  const std::string dir = temp_dir("accuracy_near_cut");
  ResultsModel m = results_model(dir);
  using Acc = DaylightFactorSummary::AccuracyReached;
  Acc above{1.0, 0.91, 2, 17500000, "target met", "met", 0, 0, "", 256};
  above.near_cut_sensors = 12;
  above.near_cut_gather_rays = 1024;
  above.near_cut_largest_percent = 1.26;
  above.near_cut_stop_reason = "gather photon part";
  m.cases[0].grids[0].daylight_factor->accuracy = above;
  Acc within = above;
  within.near_cut_largest_percent = 0.99;
  within.near_cut_gather_rays = 1936;
  within.near_cut_gather_rounds = 1;
  within.near_cut_stop_reason = "target met";
  m.cases[1].grids[0].daylight_factor->accuracy = within;
  SunAccuracyReached sun{1.0, 0.75, 9.7, 3, 11100000, "target met", "met", 0, 0, ""};
  sun.near_cut_sensors = 9;
  sun.near_cut_gather_rays = 1024;
  sun.near_cut_largest_percent = 1.22;
  sun.near_cut_stop_reason = "time budget";
  m.cases[0].grids[0].sun_accuracy = sun;
  write_results_model(m, dir);
  const std::string part = accuracy_statements(report_html(dir));
  const std::string plane = accuracy_item(part, "data-part=\"sky\" data-case=\"base\" data-grid=\"north_wing\"");
  EXPECT_NE(plane.find("Target met by the sensors it measures. The 12 sensors next to a column or partition, "
                       "estimated by final gather at 1024 rays per sensor and left out of this measure, reach up to "
                       "1.3 %: <strong>above the target</strong> (their gather rounds stopped with \"gather photon "
                       "part\"; more <code>simulation.gather_rays</code> or photons lower it)."),
            std::string::npos)
      << plane;
  const std::string ok = accuracy_item(part, "data-part=\"sky\" data-case=\"tinted\" data-grid=\"north_wing\"");
  EXPECT_NE(ok.find("Target met. The 12 sensors next to a column or partition, estimated by final gather at 1936 rays "
                    "per sensor after 1 gather round and left out of this measure, reach up to 0.99 %, within the "
                    "target."),
            std::string::npos)
      << ok;
  const std::string s = accuracy_item(part, "data-part=\"sun\" data-case=\"base\" data-grid=\"north_wing\"");
  EXPECT_NE(s.find("Target met by the sensors it measures. The 9 sensors next to a column or partition"),
            std::string::npos)
      << s;
}

TEST(ReportHtml, AGatheredGridsSunBinsStateTheirGatherRounds) {
  // A grid estimated by final gather in the sun bins' rounds: its sun sentence gives the gather
  // rays and rounds on the annual measure and, above the target, its own gather stop (the
  // photon budget, which left no room for the photons its photon part asked for) and the key
  // to change.
  const std::string dir = temp_dir("accuracy_sun_gather");
  ResultsModel m = results_model(dir);
  m.cases[0].grids[1].sun_accuracy =
      SunAccuracyReached{1.0, 1.4, 8.1, 3, 2100000, "photon budget", "above target", 2304, 2, "photon budget"};
  write_results_model(m, dir);
  const std::string html = report_html(dir);
  const std::string sun =
      accuracy_item(accuracy_statements(html), "data-part=\"sun\" data-case=\"base\" data-grid=\"east_wall\"");
  ASSERT_FALSE(sun.empty()) << html;
  EXPECT_NE(sun.find("Reached 1.4 % by final gather at 2304 rays per sensor, after 2 gather rounds following 3 rounds "
                     "of photon tracing (2.1 million photons)."),
            std::string::npos)
      << sun;
  EXPECT_NE(sun.find("more photons would, but the photon budget left no room for them. What to do: raise "
                     "<code>simulation.accuracy.max_photons</code>"),
            std::string::npos)
      << sun;
  EXPECT_EQ(sun.find("traced more photons for it"), std::string::npos) << sun;
  EXPECT_EQ(sun.find("not reachable by photons"), std::string::npos) << sun;
}

TEST(ReportHtml, AccuracyOfTheSkyAndTheSunBinsInPlainWords) {
  // A run with an accuracy target: the base grid's sky met it, its sun bins stopped on the
  // photon budget above it; the wall grid (gathered) is not reachable by photons; the variant
  // met both. The numbers are the model's, at the report's precision.
  const std::string dir = temp_dir("accuracy");
  ResultsModel m = results_model(dir);
  using Acc = DaylightFactorSummary::AccuracyReached;
  m.cases[0].grids[0].daylight_factor->accuracy =
      Acc{1.0, 0.934, 3, 4105000, "not reachable by photons", "met", 0, 0, "", 16};
  m.cases[0].grids[0].sun_accuracy = SunAccuracyReached{1.0, 1.62, 11.4, 5, 33500000, "photon budget", "above target"};
  m.cases[0].grids[1].daylight_factor->accuracy =
      Acc{1.0, 1.27, 3, 4105000, "not reachable by photons", "not reachable by photons", 0, 0, "", 16};
  m.cases[0].grids[1].sun_accuracy = SunAccuracyReached{1.0, 0.8, 7.2, 5, 33500000, "photon budget", "met"};
  m.cases[1].grids[0].daylight_factor->accuracy = Acc{1.0, 0.81, 2, 950000, "target met", "met", 0, 0, "", 16};
  m.cases[1].grids[0].sun_accuracy = SunAccuracyReached{1.0, 0.76, 9.6, 3, 4410000, "target met", "met"};
  write_results_model(m, dir);
  const std::string html = report_html(dir);
  const std::string part = accuracy_statements(html);
  ASSERT_FALSE(part.empty());
  // The sky of the base grid: target, measure, reached, rounds, photons; met, while the rounds
  // stopped for the gathered wall grid.
  const std::string sky = accuracy_item(part, "data-part=\"sky\" data-case=\"base\" data-grid=\"north_wing\"");
  EXPECT_NE(sky.find("Daylight factor (sky patches): the target is a relative standard error of at most 1.0 % at the "
                     "95th percentile of the sensors (19 sensors in 20 are at or below it). Reached 0.93 % after 3 "
                     "rounds of photon tracing (4.1 million photons). Target met. (The rounds serve every grid of "
                     "the case; they stopped with \"not reachable by photons\" for another grid.)"),
            std::string::npos)
      << sky;
  // Its sun bins: above the target, why (the photon budget) and what to do.
  const std::string sun = accuracy_item(part, "data-part=\"sun\" data-case=\"base\" data-grid=\"north_wing\"");
  EXPECT_NE(sun.find("Annual sun-bin illuminance (the indirect sunlight of every sun hour, summed over the year): "
                     "the target is a relative standard error of at most 1.0 % at the 95th percentile"),
            std::string::npos)
      << sun;
  EXPECT_NE(sun.find("Reached 1.6 % after 5 rounds of photon tracing (33.5 million photons). <strong>Above the "
                     "target.</strong> Why: the photon budget was reached first. What to do: raise "
                     "<code>simulation.accuracy.max_photons</code>"),
            std::string::npos)
      << sun;
  EXPECT_NE(sun.find("One hour's sun-bin value carries more: 11.4 % at the same percentile"), std::string::npos) << sun;
  // The gathered wall grid: not reachable by photons, and gather_rays is what lowers it.
  const std::string wall = accuracy_item(part, "data-part=\"sky\" data-case=\"base\" data-grid=\"east_wall\"");
  EXPECT_NE(wall.find("Reached 1.3 % after 3 rounds of photon tracing (4.1 million photons). <strong>Above the target "
                      "and not reachable by photons.</strong> Why: this grid's sensors are estimated by final gather"),
            std::string::npos)
      << wall;
  EXPECT_NE(wall.find("What to do: raise <code>simulation.gather_rays</code>."), std::string::npos) << wall;
  // The variant, in its own words: both met, photons below a million in whole numbers.
  const std::string vsky = accuracy_item(part, "data-part=\"sky\" data-case=\"tinted\" data-grid=\"north_wing\"");
  EXPECT_NE(vsky.find("Reached 0.81 % after 2 rounds of photon tracing (950 000 photons). Target met."), std::string::npos)
      << vsky;
  EXPECT_EQ(vsky.find("stopped with"), std::string::npos) << vsky;
  const std::string vsun = accuracy_item(part, "data-part=\"sun\" data-case=\"tinted\" data-grid=\"north_wing\"");
  EXPECT_NE(vsun.find("Reached 0.76 % after 3 rounds of photon tracing (4.4 million photons). Target met."),
            std::string::npos)
      << vsun;
  // The uncertainty table marks the gathered grid too.
  EXPECT_NE(html.find("<td>95th percentile 1.3 % (target 1.0 %; not reachable by photons; not reachable by photons "
                      "after 3 rounds)</td>"),
            std::string::npos);
  // A run with photon counts has no statements.
  EXPECT_EQ(shared_report().find("id=\"accuracy\""), std::string::npos);
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
  // wall grid and variant: DF x 2; no weather file: no sky; the report.
  EXPECT_EQ(written.size(), 10u + 1u + 2u + 2u + 1u);
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

/// The numbers of the first `points="..."` after `from` in `text` (x, y pairs).
std::vector<double> svg_points(const std::string& text, std::size_t from) {
  const std::size_t at = text.find("points=\"", from) + 8;
  std::stringstream s(text.substr(at, text.find('"', at) - at));
  std::vector<double> v;
  for (std::string pair; s >> pair;) {
    v.push_back(std::stod(pair.substr(0, pair.find(','))));
    v.push_back(std::stod(pair.substr(pair.find(',') + 1)));
  }
  return v;
}

// The base case's outdoor systems on its inline plans (as on the grid PNGs, plan_picture.h): a
// shelf outside the south window is drawn on each of its four plans (DF, DA, UDI achieved, UDI
// autonomous), south of the window and across its width, half-transparent grey, with a key
// entry; a panel 20 m away is not drawn; the wall grid (an elevation) and the variant (no
// systems) draw none and their key has no system entry.
TEST(ReportHtml, PlansDrawTheDaylightSystemsNearTheGridWithAKeyEntry) {
  const std::string dir = temp_dir("systems");
  ResultsModel m = results_model(dir);
  m.cases[0].systems = {{{1, -0.6, 2.1}, {3, -0.6, 2.1}, {3, 0, 2.1}, {1, 0, 2.1}},
                        {{1, -20, 2.1}, {3, -20, 2.1}, {3, -19, 2.1}, {1, -19, 2.1}}};
  write_results_model(m, dir);
  const std::string html = report_html(dir);
  const std::size_t base_at = html.find("id=\"grid-north_wing\""), wall_at = html.find("id=\"grid-east_wall\""),
                    variant_at = html.find("id=\"grid-tinted--north_wing\"");
  ASSERT_NE(base_at, std::string::npos);
  ASSERT_LT(base_at, wall_at);
  ASSERT_LT(wall_at, variant_at);
  const std::string base = html.substr(base_at, wall_at - base_at), wall = html.substr(wall_at, variant_at - wall_at),
                    variant = html.substr(variant_at, html.find("id=\"methods\"") - variant_at);
  EXPECT_EQ(count(base, "class=\"system\""), 4u);
  EXPECT_EQ(count(base, "daylight system (outdoors, seen from above)"), 4u);
  EXPECT_EQ(count(base, "outdoor daylight systems in grey"), 2u);  // the DF plan's caption and its label
  EXPECT_NE(base.find("fill=\"#808080\" fill-opacity=\"0.59\" stroke=\"#464646\""), std::string::npos);
  EXPECT_EQ(count(wall, "class=\"system\""), 0u);
  EXPECT_EQ(count(variant, "class=\"system\""), 0u);
  EXPECT_EQ(variant.find("daylight system (outdoors"), std::string::npos);
  // The shelf: south of the window line (larger y in the picture), as wide as the window, 0.6 m
  // deep at the plan's scale (x: 2 m of window = 2 m of shelf).
  const std::size_t plan = base.find("class=\"plot plan\"");
  const std::vector<double> shelf = svg_points(base, base.find("class=\"system\"", plan));
  const std::vector<double> window = svg_points(base, base.find("class=\"window\"", plan));
  ASSERT_EQ(shelf.size(), 8u);
  ASSERT_EQ(window.size(), 8u);
  double shelf_x0 = 1e9, shelf_x1 = -1e9, shelf_y0 = 1e9, shelf_y1 = -1e9, window_x0 = 1e9, window_x1 = -1e9, window_y = 0;
  for (std::size_t i = 0; i < 8; i += 2) {
    shelf_x0 = std::min(shelf_x0, shelf[i]);
    shelf_x1 = std::max(shelf_x1, shelf[i]);
    shelf_y0 = std::min(shelf_y0, shelf[i + 1]);
    shelf_y1 = std::max(shelf_y1, shelf[i + 1]);
    window_x0 = std::min(window_x0, window[i]);
    window_x1 = std::max(window_x1, window[i]);
    window_y += window[i + 1] / 4;
  }
  const double px_per_m = (window_x1 - window_x0) / 2;
  EXPECT_GT(px_per_m, 10);
  EXPECT_NEAR(shelf_x0, window_x0, 0.11);
  EXPECT_NEAR(shelf_x1, window_x1, 0.11);
  EXPECT_NEAR(shelf_y0, window_y, 0.11);
  EXPECT_NEAR(shelf_y1 - shelf_y0, 0.6 * px_per_m, 0.2);
  fs::remove_all(dir);
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

TEST(ReportFormat, OnePrecisionPerKindOfNumber) {
  // DF: 0.1 % from 1 % up, 2 significant digits below.
  EXPECT_EQ(format_value(2.7268, Precision::DaylightFactor), "2.7");
  EXPECT_EQ(format_value(12.34, Precision::DaylightFactor), "12.3");
  EXPECT_EQ(format_value(0.3449, Precision::DaylightFactor), "0.34");
  EXPECT_EQ(format_value(0.0345678, Precision::DaylightFactor), "0.035");
  EXPECT_EQ(format_value(0.996, Precision::DaylightFactor), "1.0");
  EXPECT_EQ(format_value(0.0, Precision::DaylightFactor), "0");
  // Lux: 3 significant digits.
  EXPECT_EQ(format_value(548.4, Precision::Illuminance), "548");
  EXPECT_EQ(format_value(1234.5, Precision::Illuminance), "1230");
  EXPECT_EQ(format_value(12.345, Precision::Illuminance), "12.3");
  EXPECT_EQ(format_value(999.7, Precision::Illuminance), "1000");
  // Shares: whole points; ratios and fractions 2 decimals; lengths and areas trimmed.
  EXPECT_EQ(format_value(98.1, Precision::Percent), "98");
  EXPECT_EQ(format_value(-0.2, Precision::Percent), "0");
  EXPECT_EQ(format_value(0.4149, Precision::Ratio), "0.41");
  EXPECT_EQ(format_value(0.6, Precision::Fraction), "0.60");
  EXPECT_EQ(format_value(1.5, Precision::Length), "1.5");
  EXPECT_EQ(format_value(6.0, Precision::Length), "6");
  EXPECT_EQ(format_value(48.04, Precision::Area), "48");
  EXPECT_EQ(format_value(std::optional<double>{}, Precision::Percent), "-");
  EXPECT_EQ(format_value(std::nan(""), Precision::Percent), "-");
  // Differences carry a sign unless zero at the shown precision.
  // Durations: 2 significant digits below 10 s, whole seconds above, never "0.00".
  EXPECT_EQ(format_value(0.004, Precision::Seconds), "< 0.01");
  EXPECT_EQ(format_value(0.0, Precision::Seconds), "< 0.01");
  EXPECT_EQ(format_value(0.0123, Precision::Seconds), "0.012");
  EXPECT_EQ(format_value(0.4249, Precision::Seconds), "0.42");
  EXPECT_EQ(format_value(4.26, Precision::Seconds), "4.3");
  EXPECT_EQ(format_value(9.96, Precision::Seconds), "10");
  EXPECT_EQ(format_value(1234.4, Precision::Seconds), "1234");
  EXPECT_EQ(format_delta(3.2, Precision::Percent), "+3");
  EXPECT_EQ(format_delta(-0.94, Precision::DaylightFactor), "-0.94");
  EXPECT_EQ(format_delta(0.01, Precision::Percent), "0");
  EXPECT_EQ(esc("<a href='x'>&\""), "&lt;a href=&#39;x&#39;&gt;&amp;&quot;");
}
