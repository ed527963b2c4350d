// A room window's frame and maintenance factors (docs/materials.md, "Frame and maintenance
// factors") scale its daylight factor in proportion: the sky component at every sensor of
// a workplane grid under the uniform sky, integrated over a fixed direction grid through
// the engine's shadow rays (engine::sky_transmittance, the direct component's rule), is
// exactly frame_factor x maintenance_factor times the one without factors. The photon part
// is scaled in expectation by the same factor (the port's transmitted weight carries it;
// engine/src/material.cpp), which the engine's glazing tests check on the material.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"

namespace dayphoton {
namespace {

std::string office(const std::string& window_extra) {
  return "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
         "outputs: {annual_illuminance: false, metrics: false}\n"
         "materials:\n"
         "  walls: {type: lambertian, reflectance: 0.5}\n"
         "  dbl:\n"
         "    type: glazing\n"
         "    panes: [{thickness: 4, transmittance: 0.89}, {thickness: 4, transmittance: 0.89}]\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: office\n"
         "      size: [6, 8, 3]\n"
         "      materials: {floor: walls, ceiling: walls, walls: walls}\n"
         "      windows:\n"
         "        - {name: w, wall: south, width: 4, height: 1.5, sill: 0.9, material: dbl" +
         window_extra + "}\n"
         "sensors:\n"
         "  grids:\n"
         "    - {name: workplane, room: office, height: 0.8, spacing: 1}\n";
}

// Sky component (fraction of the unobstructed horizontal illuminance) of each sensor under
// a uniform sky: (1/pi) sum over the upper hemisphere of T(direction) cos(theta) d omega,
// by the midpoint rule on a fixed (theta, phi) grid.
std::vector<double> sky_components(const std::string& yaml) {
  const SceneDescription d = project::build_scene_description(
      project::load_project_from_string(yaml, std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/snippet.yaml"));
  const engine::Scene scene = engine::Scene::build(d);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : d.materials) materials.push_back(engine::Material::from_spec(m));
  std::vector<double> out;
  constexpr int Thetas = 45, Phis = 90;
  for (const SensorPoint& s : d.grids.at(0).points) {
    double sum = 0;
    for (int i = 0; i < Thetas; ++i) {
      const double theta = (i + 0.5) / Thetas * 0.5 * Pi;
      for (int j = 0; j < Phis; ++j) {
        const double phi = (j + 0.5) / Phis * 2 * Pi;
        const Vec3 dir{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
        const Vec3 t = engine::sky_transmittance(scene, materials, s.position, dir);
        sum += t.y * std::cos(theta) * std::sin(theta) * (0.5 * Pi / Thetas) * (2 * Pi / Phis);
      }
    }
    out.push_back(sum / Pi);
  }
  return out;
}

TEST(WindowFactors, DaylightFactorSkyComponentScalesWithFrameTimesMaintenanceFactor) {
  const std::vector<double> plain = sky_components(office(""));
  const std::vector<double> framed = sky_components(office(", frame_factor: 0.8, maintenance_factor: 0.9"));
  ASSERT_EQ(plain.size(), framed.size());
  double mean_plain = 0, mean_framed = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_NEAR(framed[i], 0.72 * plain[i], 1e-12 * (1 + plain[i])) << "sensor " << i;
    mean_plain += plain[i];
    mean_framed += framed[i];
  }
  // The window is seen: a mean sky component of a few percent, scaled by 0.72.
  EXPECT_GT(mean_plain / static_cast<double>(plain.size()), 0.005);
  EXPECT_NEAR(mean_framed / mean_plain, 0.72, 1e-12);
}

}  // namespace
}  // namespace dayphoton
