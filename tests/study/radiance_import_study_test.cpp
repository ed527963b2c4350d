// The reference office given as RADIANCE scene files (`geometry.radiance`): the placement
// checks for geometry without rooms, and the acceptance test, whose daylight factors and DA300
// per sensor must equal projects/office's (the same room as a room generator) within the Monte
// Carlo noise of the two.
//
// The scene files are refdata's scenes/materials.rad and scenes/office.rad, read in place from
// ../shared beside the repository when it is there; otherwise (a fresh clone) from the
// identical copies in tests/data/radiance (tests/data/radiance/README.md), which
// RadianceImportStudy.RepositoryCopiesEqualRefdata checks against refdata when it can.
//
// The statistics (docs/radiance-import.md, "Validation"): each project runs with seeds 1 and 2.
// Per sensor s and quantity x (DF in %, DA300 in points), m_P(s) is the mean of project P's two
// runs and d_P(s) their difference. If the import changes nothing but the noise, the two
// projects have the same expectation and the same noise variance s2(s) per sensor, so
//   E[(m_I - m_O)^2] = s2(s)  and  E[(d_O^2 + d_I^2) / 4] = s2(s).
// Two statistics per quantity:
//   - F = sum_s (m_I - m_O)^2 / sum_s (d_O^2 + d_I^2) / 4, F-distributed with nu and 2 nu
//     degrees of freedom, nu = (sum v)^2 / sum v^2 (Satterthwaite, v = the denominator's
//     terms), judged by Paulson's normal approximation of the F distribution;
//   - the grid mean of m_I - m_O over its standard error sqrt(sum_s v_s) / N, a z value.
// The sensors' estimates are taken as independent: their photon discs barely overlap (100
// photons of 40 000 per bin), and the fixed photon count of a bin makes the grid mean less
// noisy than independence says (measured: 0.065 % against 0.11 %; docs/validation.md), so
// the bounds are conservative. Both projects run with the same seeds, so part of their noise
// is common (the same random numbers meet the same room): that too only makes the bounds
// conservative. Four statistics at a Sidak-corrected 1e-3: one-sided z < 3.48 for F,
// two-sided |z| < 3.66 for the means. The runs use a quarter of the office's photons
// (10 000 per bin). Measured (34 s of CPU for the four annual runs): DF F = 0.002 (nu 47.1),
// grid mean -0.00022 % (z -0.31); DA300 F = 0.000 (nu 15.6), grid mean -0.0034 points
// (z -0.06). From the noise of one run (about 2.8 % per sensor at these photons), a glass
// mapped as tn = Tn (9 % more light) would give F near 10, a 1 % bias of every sensor a
// grid-mean z near 4.5.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fresh_run.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/placement_check.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "../radiance_in_units.h"
#include "../temp_folder.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

const fs::path Refdata = fs::path(DAYPHOTON_SOURCE_DIR).parent_path() / "shared" / "refdata" / "scenes";
const fs::path RepositoryCopies = fs::path(DAYPHOTON_TEST_DATA_DIR) / "radiance";

fs::path scene_folder() { return fs::exists(Refdata / "office.rad") ? Refdata : RepositoryCopies; }

std::string imported_office_yaml(const std::string& sensors) {
  const fs::path dir = scene_folder();
  return "version: 1\n"
         "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
         "geometry:\n"
         "  radiance:\n"
         "    - files: [" + (dir / "materials.rad").string() + ", " + (dir / "office.rad").string() + "]\n"
         "      ports: auto\n"
         "sensors:\n" + sensors +
         "outputs: {annual_illuminance: false, metrics: false}\n";
}

const std::string WorkPlane =
    "  grids:\n"
    "    - {name: workplane, polygon: [[0, 0, 0], [6, 0, 0], [6, 8, 0], [0, 8, 0]], height: 0.8,\n"
    "       spacing: 0.5, inset: 0.5}\n";

std::vector<std::string> placement_errors(const std::string& yaml) {
  try {
    const project::Project p = project::load_project_from_string(yaml, "imported.yaml");
    SceneDescription d = project::build_scene_description(p);
    const engine::Scene scene = engine::Scene::build(d);
    check_placement(scene, d.grids, p);
  } catch (const InputError& e) {
    std::vector<std::string> out;
    for (const Diagnostic& d : e.diagnostics()) out.push_back(d.message);
    return out;
  }
  return {};
}

TEST(RadianceImportStudy, RepositoryCopiesEqualRefdata) {
  if (!fs::exists(Refdata)) GTEST_SKIP() << "no " << Refdata << " beside the repository";
  for (const char* name : {"materials.rad", "office.rad"}) {
    std::ifstream a(Refdata / name), b(RepositoryCopies / name);
    std::stringstream sa, sb;
    sa << a.rdbuf();
    sb << b.rdbuf();
    EXPECT_EQ(sa.str(), sb.str()) << name;
  }
}

TEST(RadianceImportStudy, AutoPortsMakeTheWindowTheOnlyPort) {
  const project::Project p = project::load_project_from_string(imported_office_yaml(WorkPlane), "imported.yaml");
  SceneDescription d = project::build_scene_description(p);
  const engine::Scene scene = engine::Scene::build(d);
  ASSERT_EQ(scene.ports().size(), 1u);
  EXPECT_EQ(scene.ports()[0].name, "window");
  EXPECT_NEAR(scene.ports()[0].normal.y, 1.0, 1e-12);  // into the room
  EXPECT_NEAR(scene.ports()[0].area_m2, 6.0, 1e-12);
  EXPECT_NO_THROW(check_placement(scene, d.grids, p));
}

TEST(RadianceImportStudy, PlacementChecksWorkWithoutRooms) {
  // A sensor in the room and one 2 m outside the window wall: the second sees the sky without
  // a port (the check casts rays; it needs no room generator).
  const std::string points =
      "  points:\n"
      "    - {name: desks, points: [[3, 4, 0.8, 0, 0, 1], [3, -2, 0.8, 0, 0, 1]]}\n";
  const std::vector<std::string> errors = placement_errors(imported_office_yaml(points));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("sensor set 'desks': 1 of 2 sensors lie outside every room (sensor 1 at (3, -2, 0.8)"),
            std::string::npos)
      << errors[0];
  // Without ports (an empty list) no light can enter: the project's error says so.
  std::string no_ports = imported_office_yaml(WorkPlane);
  no_ports.replace(no_ports.find("ports: auto"), 11, "ports: []");
  const std::vector<std::string> none = placement_errors(no_ports);
  ASSERT_FALSE(none.empty());
  EXPECT_NE(none[0].find("the project has no photon port"), std::string::npos) << none[0];
}

TEST(RadianceImportStudy, APtsFileInFeetOutsideTheModelNamesTheUnitsKey) {
  // The office's work plane written in feet, beside the office in metres: sensors up to
  // 24.6 ft = 24.6 "m" away, outside the room; scaled by 0.3048 they all lie in it.
  const fs::path dir = test::process_temp_dir() / "pts_in_feet";
  fs::create_directories(dir);
  {
    std::ifstream in(RepositoryCopies / "grid_0p8m.pts");
    std::ofstream out(dir / "grid_ft.pts");
    for (double x, y, z, nx, ny, nz; in >> x >> y >> z >> nx >> ny >> nz;)
      out << x / 0.3048 << ' ' << y / 0.3048 << ' ' << z / 0.3048 << ' ' << nx << ' ' << ny << ' ' << nz << '\n';
  }
  const std::string file = (dir / "grid_ft.pts").string();
  const std::vector<std::string> errors =
      placement_errors(imported_office_yaml("  points:\n    - {name: desks, file: " + file + "}\n"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("lie outside every room"), std::string::npos) << errors[0];
  EXPECT_NE(errors[0].find("; scaled by 0.3048 they all lie inside the model's bounding box: if '" + file +
                           "' is in feet, set 'units: Feet' on this entry"),
            std::string::npos)
      << errors[0];
  // With the key the sensors are the work plane's, all in the room.
  EXPECT_TRUE(placement_errors(imported_office_yaml("  points:\n    - {name: desks, file: " + file + ", units: Feet}\n"))
                  .empty());
  // Inline points outside the room get no such hint (they are in metres by definition).
  const std::vector<std::string> inline_errors = placement_errors(
      imported_office_yaml("  points:\n    - {name: desks, points: [[3, 4, 0.8, 0, 0, 1], [9.8, 13.1, 2.6, 0, 0, 1]]}\n"));
  ASSERT_EQ(inline_errors.size(), 1u);
  EXPECT_EQ(inline_errors[0].find("scaled by"), std::string::npos) << inline_errors[0];
}

// ---- the acceptance test ------------------------------------------------------------------

/// Column `column` of a results CSV (header names), in row order; also x, y, z for checks.
std::vector<double> csv_column(const fs::path& file, const std::string& column) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  {
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) header.push_back(f);
  }
  std::size_t index = header.size();
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == column) index = i;
  if (index == header.size()) throw std::runtime_error("no column " + column + " in " + file.string());
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string f;
    for (std::size_t i = 0; i <= index; ++i) std::getline(ss, f, ',');
    values.push_back(std::stod(f));
  }
  return values;
}

struct StudyResults {
  std::vector<double> df_percent, da300_percent, x, y, z;
};

StudyResults run_case(project::Project p, unsigned long long seed, const std::string& label) {
  p.simulation.seed = seed;
  p.outputs.daylight_factor = p.outputs.annual_illuminance = p.outputs.metrics = true;
  p.outputs.images = p.outputs.report = p.outputs.coefficients = false;
  const fs::path out = test::process_temp_dir() / ("radiance_import_" + label + std::to_string(seed));
  test::run_in_fresh_folder(p, out);
  StudyResults r;
  const fs::path grid = out / "workplane";
  r.df_percent = csv_column(grid / "daylight_factor.csv", "df_percent");
  r.x = csv_column(grid / "daylight_factor.csv", "x");
  r.y = csv_column(grid / "daylight_factor.csv", "y");
  r.z = csv_column(grid / "daylight_factor.csv", "z");
  r.da300_percent = csv_column(grid / "metrics.csv", "da300_percent");
  fs::remove_all(out);
  return r;
}

/// Paulson's normal approximation of the F distribution (M. Abramowitz and I. Stegun,
/// "Handbook of Mathematical Functions", 26.6.15): the z value of F with nu1, nu2 degrees.
double paulson_z(double f, double nu1, double nu2) {
  const double a = 2.0 / (9.0 * nu1), b = 2.0 / (9.0 * nu2);
  const double c = std::cbrt(f);
  return ((1 - b) * c - (1 - a)) / std::sqrt(b * c * c + a);
}

constexpr double FBound_z = 3.48;     ///< one-sided, 1 - (1 - 1e-3)^(1/4) = 2.5e-4
constexpr double MeanBound_z = 3.66;  ///< two-sided, the same

/// The two statistics of the header for one quantity; prints them.
void expect_same_within_noise(const char* what, const std::vector<double>& o1, const std::vector<double>& o2,
                              const std::vector<double>& i1, const std::vector<double>& i2) {
  const std::size_t n = o1.size();
  double num = 0, den = 0, den2 = 0, mean_diff = 0;
  for (std::size_t s = 0; s < n; ++s) {
    const double mo = 0.5 * (o1[s] + o2[s]), mi = 0.5 * (i1[s] + i2[s]);
    const double v = (std::pow(o1[s] - o2[s], 2) + std::pow(i1[s] - i2[s], 2)) / 4;
    num += (mi - mo) * (mi - mo);
    den += v;
    den2 += v * v;
    mean_diff += mi - mo;
  }
  mean_diff /= double(n);
  if (den == 0) {  // no noise at all: the two must agree exactly
    EXPECT_EQ(num, 0.0) << what;
    return;
  }
  const double nu = den * den / den2;
  const double f = num / den;
  const double z_f = paulson_z(f, nu, 2 * nu);
  const double z_mean = mean_diff / (std::sqrt(den) / double(n));
  std::printf("[ radiance import ] %s: F = %.3f (nu = %.1f, z = %+.2f; bound %.2f), grid mean difference %+.5f "
              "(z = %+.2f; bound %.2f)\n",
              what, f, nu, z_f, FBound_z, mean_diff, z_mean, MeanBound_z);
  EXPECT_LT(z_f, FBound_z) << what << ": the imported office differs per sensor beyond the noise";
  EXPECT_LT(std::abs(z_mean), MeanBound_z) << what << ": the imported office's grid mean differs beyond the noise";
}

TEST(RadianceImportStudy, ImportedOfficeGivesTheOfficesDaylightFactorAndDa300) {
  const std::string office_path = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml";
  project::Project office = project::load_project(office_path);
  project::Project imported = project::load_project_from_string(imported_office_yaml(WorkPlane), office_path);
  // Everything but the geometry, its materials and the grid's outline is the office's own.
  imported.site = office.site;
  imported.weather = office.weather;
  imported.study = project::StudyKind::Annual;  // loaded without weather: a daylight-factor study
  imported.simulation = office.simulation;
  imported.metrics = office.metrics;
  ASSERT_TRUE(imported.geometry.rooms.empty());

  // A quarter of the office's photons, in both projects alike: the bounds come from the runs'
  // own noise, so fewer photons only widen them (by 2x), which still leaves the mapping errors
  // above far outside them, and the four annual runs take a quarter of the time.
  office.simulation.photons_per_bin /= 4;
  imported.simulation.photons_per_bin /= 4;
  const StudyResults o1 = run_case(office, 1, "office"), o2 = run_case(office, 2, "office");
  const StudyResults i1 = run_case(imported, 1, "imported"), i2 = run_case(imported, 2, "imported");
  ASSERT_EQ(o1.df_percent.size(), 165u);
  ASSERT_EQ(i1.df_percent.size(), 165u);
  for (std::size_t s = 0; s < 165; ++s) {  // the same sensors, in the same order
    EXPECT_DOUBLE_EQ(i1.x[s], o1.x[s]);
    EXPECT_DOUBLE_EQ(i1.y[s], o1.y[s]);
    EXPECT_DOUBLE_EQ(i1.z[s], o1.z[s]);
  }
  expect_same_within_noise("DF %", o1.df_percent, o2.df_percent, i1.df_percent, i2.df_percent);
  expect_same_within_noise("DA300 points", o1.da300_percent, o2.da300_percent, i1.da300_percent,
                           i2.da300_percent);
}

// ---- the office in feet ----------------------------------------------------------------------

/// One daylight-factor run: DF, its stated standard error and the sensors' positions.
struct DfResults {
  std::vector<double> df_percent, stderr_percent, x, y, z;
};

DfResults run_df_case(project::Project p, unsigned long long seed, const std::string& label) {
  p.simulation.seed = seed;
  p.outputs.images = p.outputs.report = p.outputs.coefficients = false;
  const fs::path out = test::process_temp_dir() / ("radiance_units_" + label + std::to_string(seed));
  test::run_in_fresh_folder(p, out);
  const fs::path csv = out / "workplane" / "daylight_factor.csv";
  DfResults r{csv_column(csv, "df_percent"), csv_column(csv, "df_stderr_percent"), csv_column(csv, "x"),
              csv_column(csv, "y"), csv_column(csv, "z")};
  fs::remove_all(out);
  return r;
}

// The office's scene files rewritten in feet (every vertex / 0.3048, as a US exporter writes
// them) and read with `units: Feet`, against the same files in metres (docs/radiance-import.md,
// "Units"): the same sensors and port area, and the same daylight factors within the noise, by
// the statistics of the acceptance test above (two seeds each) and per sensor against the
// stated standard errors (seed 1 in metres against seed 2 in feet: independent runs, so
// z = (a - b) / sqrt(se_a^2 + se_b^2) has unit variance if the errors are honest; its RMS over
// 165 sensors is 1 +- 0.06, bounded at 1.5). Without `units` the room is 3.28 times as large
// and the sensors sit in its corner: every statistic fails by far. Measured: see the printout.
TEST(RadianceImportStudy, OfficeInFeetWithUnitsGivesTheOfficesDaylightFactors) {
  const fs::path dir = test::process_temp_dir() / "office_in_feet";
  fs::create_directories(dir);
  {
    std::ifstream in(scene_folder() / "office.rad");
    std::stringstream text;
    text << in.rdbuf();
    std::ofstream(dir / "office_ft.rad") << test::radiance_in_units(text.str(), 0.3048);
  }
  std::string feet_yaml = imported_office_yaml(WorkPlane);
  const std::string office_rad = (scene_folder() / "office.rad").string();
  feet_yaml.replace(feet_yaml.find(office_rad), office_rad.size(), (dir / "office_ft.rad").string());
  const std::string ports = "      ports: auto\n";
  feet_yaml.replace(feet_yaml.find(ports), ports.size(), ports + "      units: Feet\n");
  const std::string office_path = std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml";
  project::Project metric = project::load_project_from_string(imported_office_yaml(WorkPlane), office_path);
  project::Project feet = project::load_project_from_string(feet_yaml, office_path);
  ASSERT_EQ(feet.geometry.radiance[0].units, "Feet");
  const project::Project office = project::load_project(office_path);
  for (project::Project* p : {&metric, &feet}) {
    p->simulation = office.simulation;
    p->simulation.photons_per_bin /= 4;  // as the acceptance test above
    ASSERT_EQ(p->study, project::StudyKind::DaylightFactor);
  }
  {  // the same port, area in m2
    SceneDescription d = project::build_scene_description(feet);
    EXPECT_TRUE(d.warnings.empty());
    const engine::Scene scene = engine::Scene::build(d);
    ASSERT_EQ(scene.ports().size(), 1u);
    EXPECT_NEAR(scene.ports()[0].area_m2, 6.0, 1e-9);
  }
  const DfResults m1 = run_df_case(metric, 1, "metric"), m2 = run_df_case(metric, 2, "metric");
  const DfResults f1 = run_df_case(feet, 1, "feet"), f2 = run_df_case(feet, 2, "feet");
  ASSERT_EQ(m1.df_percent.size(), 165u);
  ASSERT_EQ(f1.df_percent.size(), 165u);
  double sum_z2 = 0, same_seed_m = 0;
  for (std::size_t s = 0; s < 165; ++s) {
    same_seed_m = std::max(same_seed_m, std::abs(f1.df_percent[s] - m1.df_percent[s]));
    EXPECT_DOUBLE_EQ(f1.x[s], m1.x[s]);
    EXPECT_DOUBLE_EQ(f1.y[s], m1.y[s]);
    EXPECT_DOUBLE_EQ(f1.z[s], m1.z[s]);
    const double z = (f2.df_percent[s] - m1.df_percent[s]) /
                     std::sqrt(f2.stderr_percent[s] * f2.stderr_percent[s] + m1.stderr_percent[s] * m1.stderr_percent[s]);
    sum_z2 += z * z;
  }
  const double rms_z = std::sqrt(sum_z2 / 165);
  std::printf("[ radiance units ] feet against metres, per sensor by the stated errors: RMS z = %.3f; the same seed: "
              "largest difference %.2g DF %%\n",
              rms_z, same_seed_m);
  EXPECT_LT(rms_z, 1.5);
  expect_same_within_noise("DF % (feet)", m1.df_percent, m2.df_percent, f1.df_percent, f2.df_percent);
}

}  // namespace
}  // namespace dayphoton::study
