// A port that transmits diffusely (a translucent roof light, transmitted_specular 0) seen by
// sensors a final gather estimates (a point set), against a closed form and against the
// receiver plane's estimate at the same points.
//
// Closed form. A black room (every reflectance 0, ground 0) under the CIE standard overcast
// sky with a horizontal roof light flush with the ceiling: nothing outside shades the pane, so
// its sky-side irradiance is the horizontal illuminance E_h. A Lambertian transmitter of
// diffuse transmittance tau_d then has the room-side radiance L = tau_d E_h / pi over the whole
// pane, and nothing else in the room is lit, so a sensor at x (unit normal n) with the pane
// wholly in front of it receives E = L PSA, PSA the pane's projected solid angle by Lambert's
// formula E/L = 1/2 |sum_i gamma_i (n . unit(v_i x v_{i+1}))| (v_i the pane's vertices
// relative to x, gamma_i the angle between consecutive ones; Lambert, Photometria (1760); see
// Ashdown, "Near-field photometry: a new approach", J. IES 22 (1993), eq. 1). So
// DF = 100 E / E_h = 100 tau_d PSA / pi.
//
// Tolerance: each point within 4 of its own reported standard errors of the closed form, plus
// 3 % of it for the density estimate's bias at the pane's edges (the lookup disc is cut there).
// Measured (this project at 40 000 photons per bin, 4096 gather rays, seed 8): the point
// below the pane 3.408 +- 0.054 % against 3.448 % (the plane 3.466 +- 0.059 %), all five
// within 0.8 of their standard errors of the closed form. Before the tracer stored the photons on a diffusing port's sky
// side the points read 0 (the direct component takes only the straight part, here none).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/study_runner.h"
#include "fresh_run.h"
#include "../temp_folder.h"
#include "numeric_csv.h"

namespace dayphoton::study {
namespace {

namespace fs = std::filesystem;

constexpr double Pi = 3.14159265358979323846;
// The pane: x, y 1.4..2.6 at z = 3 (a 4 x 4 x 3 m room, a centred 1.2 x 1.2 m roof light).
constexpr double PaneX0 = 1.4, PaneX1 = 2.6, PaneZ = 3.0;
// translucent {reflectance 0.5, transmissivity 0.8, transmitted_specular 0}: tau_d = 0.4.
constexpr double TauD = 0.5 * 0.8;

/// Lambert's formula for the pane seen from `x` facing `n` (the pane wholly in front of x).
double pane_projected_solid_angle(const Vec3& x, const Vec3& n) {
  const Vec3 v[4] = {Vec3{PaneX0, PaneX0, PaneZ} - x, Vec3{PaneX1, PaneX0, PaneZ} - x,
                     Vec3{PaneX1, PaneX1, PaneZ} - x, Vec3{PaneX0, PaneX1, PaneZ} - x};
  double sum = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = normalize(v[i]), b = normalize(v[(i + 1) % 4]);
    const double gamma = std::acos(std::fmax(-1.0, std::fmin(1.0, dot(a, b))));
    sum += gamma * dot(n, normalize(cross(a, b)));
  }
  return 0.5 * std::fabs(sum);
}

using test::read_csv;

/// Runs the black room with the opal roof light (`simulation_extra` appended to the
/// simulation map) and checks the points, and the plane at the same points, against the
/// closed form.
void expect_closed_form(const std::string& simulation_extra) {
  const fs::path dir = test::process_temp_dir() /
                       ("dayphoton_diffusing_port_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "project.yaml") <<
      "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
      "study: daylight_factor\n"
      "materials:\n"
      "  black: {type: lambertian, reflectance: 0}\n"
      "  opal: {type: translucent, reflectance: 0.5, transmissivity: 0.8, transmitted_specular: 0}\n"
      "geometry:\n"
      "  rooms:\n"
      "    - name: room\n"
      "      size: [4, 4, 3]\n"
      "      materials: {floor: black, ceiling: black, walls: black}\n"
      "      roof_lights: [{name: opal_light, width: 1.2, length: 1.2, material: opal}]\n"
      "sensors:\n"
      "  grids: [{name: plane, room: room, height: 0.8, spacing: 0.5, inset: 0.5}]\n"
      "  points:\n"
      "    - name: points\n"
      "      points: [[2, 2, 0.8, 0, 0, 1], [1, 1, 0.8, 0, 0, 1], [2, 3.5, 0.8, 0, 0, 1], [3.5, 0.5, 0.8, 0, 0, 1],\n"
      "               [0.5, 2, 1.5, 1, 0, 0]]\n"
      "simulation: {photons_per_bin: 4000, seed: 7, ground_reflectance: 0" + simulation_extra + "}\n"
      "outputs: {images: false, report: false}\n";
  test::run_file_in_fresh_folder(dir / "project.yaml", dir / "out");
  const std::vector<std::vector<double>> points = read_csv(dir / "out" / "points" / "daylight_factor.csv");
  const std::vector<std::vector<double>> plane = read_csv(dir / "out" / "plane" / "daylight_factor.csv");
  fs::remove_all(dir);
  ASSERT_EQ(points.size(), 5u);
  for (const std::vector<double>& row : points) {
    ASSERT_EQ(row.size(), 6u);  // index, x, y, z, df_percent, df_stderr_percent
    const Vec3 x{row[1], row[2], row[3]};
    const Vec3 n = row[3] > 1 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
    const double closed = 100 * TauD * pane_projected_solid_angle(x, n) / Pi;
    EXPECT_NEAR(row[4], closed, 4 * row[5] + 0.03 * closed) << "point (" << x.x << ", " << x.y << ", " << x.z << ")";
    if (n.z == 1) {
      // The receiver plane's estimate at the same point (it counts the photons crossing it).
      for (const std::vector<double>& p : plane)
        if (std::fabs(p[1] - x.x) < 1e-9 && std::fabs(p[2] - x.y) < 1e-9) {
          EXPECT_NEAR(p[4], closed, 4 * p[5] + 0.03 * closed) << "plane at (" << x.x << ", " << x.y << ")";
          EXPECT_NEAR(row[4], p[4], 4 * std::hypot(row[5], p[5]) + 0.03 * closed) << "(" << x.x << ", " << x.y << ")";
        }
    }
  }
}

TEST(DiffusingPort, GatheredPointsReadTheLightALambertianRoofLightTransmits) { expect_closed_form(""); }

// The region of interest ends 1 cm below the pane, so the pane's sky side lies outside it:
// the Direct records there are kept all the same (the gather below reads them). Before, the
// points read 0.
TEST(DiffusingPort, APortOutsideTheRegionOfInterestStillGivesTheGatherItsLight) {
  expect_closed_form(", region_of_interest: {origin: [0, 0, 0], size: [4, 4, 2.99]}");
}

}  // namespace
}  // namespace dayphoton::study
