// report.html (study/report_html.h) from a synthetic results folder written with the study's
// own writers: every section is present and listed for the page's self-check, every plot has
// drawn content, nothing is fetched from the network, values and pass/fail verdicts come from
// the files, names are escaped, variants and missing tables are handled, the text is
// deterministic, and a folder without summary.json is an input error. (The page is opened in a
// real browser by tests/report/.)
#include "dayphoton/study/report_html.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/result_files.h"

using namespace dayphoton;
using namespace dayphoton::study;
namespace fs = std::filesystem;

namespace {

std::string temp_dir(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("dayphoton_report_html_test_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p.string();
}

/// A 4 x 3 grid at 0.8 m with DF, metrics and a year of hourly illuminance.
void write_grid(const std::string& dir, bool with_metrics) {
  fs::create_directories(dir);
  std::vector<SensorPoint> sensors;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) sensors.push_back({{0.5 + i, 0.5 + j, 0.8}, {0, 0, 1}});
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

const char* const GridJson = R"({"name": "north_wing", "sensors": 12,
  "daylight_factor_percent": {"mean": 3.85, "median": 3.85, "min": 0.0, "max": 7.7, "uniformity": 0.0,
                              "area_at_or_above": [{"threshold_percent": 2.0, "area_percent": 66.6667}]},
  "annual": {"sensors": 12, "time_steps": 8760, "occupied_hours": 3650, "sda_percent": 60.0, "sda_sensors": 7,
             "ase_percent": 12.5,
             "occupancy": {"start_h": 8.0, "end_h": 18.0},
             "thresholds": {"da_lux": 300.0, "udi_lower_lux": 100.0, "udi_upper_original_lux": 2000.0,
                            "udi_upper_revised_lux": 3000.0, "sda_time_fraction": 0.5,
                            "ase_threshold_lux": 1000.0, "ase_hours": 250.0},
             "mean": {"da300_percent": 44.0, "cda300_percent": 50.0, "damax_percent": 1.0,
                      "udi_below100_percent": 20.0, "udi100_2000_percent": 50.0, "udi_above2000_percent": 30.0,
                      "udi_supplementary100_300_percent": 10.0, "udi_autonomous300_3000_percent": 40.0,
                      "udi_above3000_percent": 30.0, "mean_occupied_lux": 550.0},
             "en17037": {"daylight_hours": 4380, "daylight_hours_source": "test",
                         "levels": [{"level": "minimum", "target_lux": 300.0, "target_area_percent": 80.0,
                                     "minimum_target_lux": 100.0, "minimum_target_area_percent": 100.0, "passes": true},
                                    {"level": "medium", "target_lux": 500.0, "target_area_percent": 40.0,
                                     "minimum_target_lux": 300.0, "minimum_target_area_percent": 80.0, "passes": false}]},
             "sky": "synthetic"}})";

/// A results folder: base grid with everything, one variant whose grid lacks metrics.
std::string write_results(const std::string& name) {
  const std::string dir = temp_dir(name);
  write_grid(dir + "/north_wing", true);
  write_grid(dir + "/variants/tinted/north_wing", false);
  std::string variant_grid = GridJson;
  variant_grid = std::regex_replace(variant_grid, std::regex(R"("annual": \{[\s\S]*\}\})"), "\"x\": 0}");
  std::ofstream(dir + "/summary.json")
      << R"({"project": "/nonexistent/project.yaml", "output": ")" << dir << R"(",
  "site": {"name": "Test <site> & co", "latitude_deg": 51.5, "longitude_deg": -0.12, "time_zone_h": 0.0},
  "weather": "/nonexistent/weather.epw",
  "simulation": {"basis": "tregenza", "photons_per_bin": 1000, "seed": 1},
  "cache": {"sources": 146, "sources_traced": 146, "sources_cached": 0, "grids_estimated": 1, "grids_cached": 0},
  "timings": [{"step": "photons", "seconds": 2.5, "work": 146, "unit": "sources", "cached": false},
              {"step": "annual north_wing", "seconds": 0.25, "work": 8760, "unit": "hours", "cached": true}],
  "notes": ["a note"],
  "grids": [)" << GridJson << R"(],
  "variants": [{"name": "tinted", "grids": [)" << variant_grid << R"(]}]})";
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

TEST(ReportHtml, ValuesAndVerdictsComeFromTheFiles) {
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
  // Run time: the sum of the steps; the cached step says so.
  EXPECT_NE(html.find("<b>2.75</b>"), std::string::npos);
  EXPECT_NE(html.find("<td>cache</td>"), std::string::npos);
  // The variant's grid has no annual results and says so, without failing the report.
  const std::size_t variant = html.find("id=\"grid-tinted--north_wing\"");
  ASSERT_NE(variant, std::string::npos);
  EXPECT_NE(html.find("metrics.csv not found", variant), std::string::npos);
  // Without the project file the plans fall back to the sensors' extent, and say so.
  EXPECT_NE(html.find("is not available: plans show the sensors"), std::string::npos);
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
  // Base grid: DF + 4 metrics x (EXR + PNG); variant: DF x 2; no weather file: no sky; the report.
  EXPECT_EQ(written.size(), 10u + 2u + 1u);
  EXPECT_TRUE(fs::exists(dir + "/variants/tinted/north_wing/daylight_factor.exr"));
  EXPECT_TRUE(fs::exists(dir + "/north_wing/da300.png"));
  EXPECT_TRUE(fs::exists(dir + "/report.html"));
}

// A wall grid's plan is an elevation in the wall's plane: the south window of the office
// must not be drawn on the back (north) wall's picture, while the work plane's plan shows it.
TEST(ReportHtml, ElevationsShowOnlyTheWindowsOfTheirWall) {
  const std::string dir = temp_dir("elevation");
  const std::string project = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/wall_sensors/project.yaml";
  std::vector<SensorPoint> wall, plane;
  for (int iv = 0; iv < 5; ++iv)
    for (int iu = 0; iu < 11; ++iu) wall.push_back({{0.5 + 0.5 * iu, 8, 0.5 + 0.5 * iv}, {0, -1, 0}});
  for (int iy = 0; iy < 15; ++iy)
    for (int ix = 0; ix < 11; ++ix) plane.push_back({{0.5 + 0.5 * ix, 0.5 + 0.5 * iy, 0.8}, {0, 0, 1}});
  for (const auto& [name, sensors] : {std::pair{std::string("back_wall"), wall}, std::pair{std::string("workplane"), plane}}) {
    fs::create_directories(dir + "/" + name);
    write_sensors_csv(sensors, dir + "/" + name + "/sensors.csv");
    write_daylight_factor_csv(sensors, std::vector<double>(sensors.size(), 1.0), dir + "/" + name + "/daylight_factor.csv");
  }
  auto grid = [](const std::string& name, std::size_t n) {
    return R"({"name": ")" + name + R"(", "sensors": )" + std::to_string(n) +
           R"(, "daylight_factor_percent": {"mean": 1, "median": 1, "min": 1, "max": 1, "uniformity": 1,
              "area_at_or_above": [{"threshold_percent": 2.0, "area_percent": 0}]}})";
  };
  std::ofstream(dir + "/summary.json") << R"({"project": ")" << project << R"(", "output": ")" << dir << R"(",
    "site": {"name": "office", "latitude_deg": 37.72, "longitude_deg": -122.22, "time_zone_h": -8.0},
    "simulation": {"basis": "tregenza", "photons_per_bin": 1000, "seed": 1},
    "grids": [)" << grid("back_wall", wall.size()) << ", " << grid("workplane", plane.size()) << R"(],
    "variants": []})";
  const std::string html = report_html(dir);
  const std::size_t wall_at = html.find("id=\"grid-back_wall\""), plane_at = html.find("id=\"grid-workplane\"");
  ASSERT_NE(wall_at, std::string::npos);
  ASSERT_NE(plane_at, std::string::npos);
  ASSERT_LT(wall_at, plane_at);
  EXPECT_EQ(count(html.substr(wall_at, plane_at - wall_at), "class=\"window\""), 0u);
  EXPECT_GE(count(html.substr(plane_at), "class=\"window\""), 1u);
}

TEST(ReportHtml, NamesFromTheSummaryCannotLeadOutOfTheResultsFolder) {
  // A hand-edited summary.json names a grid folder outside the results folder: by a name
  // with '..', or by its recorded absolute "folder" (the name's own folder being absent).
  // The report used to write its images there.
  const std::string outside = temp_dir("outside");
  write_grid(outside + "/grid", false);
  // By name: an input error.
  std::string dir = temp_dir("escape");
  std::ofstream(dir + "/summary.json") << R"({"grids": [{"name": "../dayphoton_report_html_test_outside/grid"}]})";
  EXPECT_THROW(write_images_and_report(dir), InputError);
  EXPECT_FALSE(fs::exists(outside + "/grid/daylight_factor.exr"));
  // By the recorded folder: ignored, the grid's own folder (absent) is what counts.
  dir = temp_dir("escape_recorded");
  std::ofstream(dir + "/summary.json") << R"({"grids": [{"name": "gone", "folder": ")" << outside << R"(/grid"}]})";
  write_images_and_report(dir);
  EXPECT_FALSE(fs::exists(outside + "/grid/daylight_factor.exr"));
  dir = temp_dir("escape_variant");
  std::ofstream(dir + "/summary.json") << R"({"variants": [{"name": "..", "grids": [{"name": "grid"}]}]})";
  try {
    write_images_and_report(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostics().at(0).message, "variant name '..' is not a portable folder name: it starts with '.'");
  }
}

TEST(ReportHtml, PlansComeFromAProjectWhoseOutputFolderLiesElsewhere) {
  // A project run with --output may name an outputs.folder outside its own folder; the
  // report reads only its geometry, so it must still load.
  const std::string dir = temp_dir("elsewhere");
  std::ofstream(dir + "/project.yaml")
      << "site: {latitude: 51.5, longitude: -0.12, time_zone: 0}\n"
         "outputs: {annual_illuminance: false, metrics: false, folder: /elsewhere}\n"
         "materials: {walls: {type: lambertian, reflectance: 0.5}}\n"
         "geometry:\n"
         "  rooms: [{name: office, size: [4, 3, 3], materials: {floor: walls, ceiling: walls, walls: walls}}]\n"
         "sensors: {grids: [{name: north_wing, room: office, height: 0.8, spacing: 1}]}\n";
  write_grid(dir + "/north_wing", false);
  std::ofstream(dir + "/summary.json") << R"({"project": ")" << dir << R"(/project.yaml", "grids": [{"name": "north_wing"}]})";
  const std::string html = report_html(dir);
  EXPECT_NE(html.find("as it is now"), std::string::npos);
  EXPECT_EQ(html.find("no longer loads"), std::string::npos);
}

// A variant's plan shows its own windows (a removed window is not drawn), and its section
// says what it changes.
TEST(ReportHtml, AVariantsPlanShowsItsOwnWindowsAndItsChanges) {
  const std::string dir = temp_dir("variant_windows");
  std::ofstream(dir + "/project.yaml")
      << "site: {latitude: 51.5, longitude: -0.12, time_zone: 0}\n"
         "outputs: {annual_illuminance: false, metrics: false}\n"
         "materials: {walls: {type: lambertian, reflectance: 0.5}, glazing: {type: glass, transmittance: 0.6}}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [4, 3, 3]\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows: [{name: south, wall: south, width: 2, height: 1, sill: 1, material: glazing}]\n"
         "sensors: {grids: [{name: north_wing, room: office, height: 0.8, spacing: 1}]}\n"
         "variants: [{name: blank, remove: {windows: [south]}}]\n";
  write_grid(dir + "/north_wing", false);
  write_grid(dir + "/variants/blank/north_wing", false);
  std::ofstream(dir + "/summary.json") << R"({"project": ")" << dir << R"(/project.yaml",
    "grids": [{"name": "north_wing"}],
    "variants": [{"name": "blank", "changes": ["window south removed"], "grids": [{"name": "north_wing"}]}]})";
  const std::string html = report_html(dir);
  const std::size_t base_at = html.find("id=\"grid-north_wing\""), variant_at = html.find("id=\"grid-blank--north_wing\"");
  ASSERT_NE(base_at, std::string::npos);
  ASSERT_NE(variant_at, std::string::npos);
  ASSERT_LT(base_at, variant_at);
  EXPECT_GE(count(html.substr(base_at, variant_at - base_at), "class=\"window\""), 1u);
  EXPECT_EQ(count(html.substr(variant_at), "class=\"window\""), 0u);
  EXPECT_NE(html.find("changes: window south removed", variant_at), std::string::npos);
  EXPECT_EQ(html.substr(base_at, variant_at - base_at).find("changes:"), std::string::npos);
}

TEST(ReportHtml, AFolderWithoutSummaryIsAnInputError) {
  const std::string dir = temp_dir("empty");
  try {
    report_html(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("summary.json"), std::string::npos);
  }
  std::ofstream(dir + "/summary.json") << "[1, 2";
  EXPECT_THROW(report_html(dir), InputError);
}
