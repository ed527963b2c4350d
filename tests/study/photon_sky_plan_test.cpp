// The plan asks for the daylight factor's photon part under the continuous sky
// (engine/photon_part_on_sky.h): the sky sources' photons carry sky ratios taken against the DF
// sky's bin means, the sky coefficients the bin radiances, the sun bins neither; and the ratios'
// key follows the sky's shape and the basis, not the ground (a changed ground keeps the photons).
#include <gtest/gtest.h>

#include <string>

#include "dayphoton/engine/photon.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/simulation_plan.h"

namespace dayphoton::study {
namespace {

std::string project_text(double ground_reflectance, const std::string& basis) {
  return "site: {latitude: 37.72, longitude: -122.22, time_zone: -8}\n"
         "study: daylight_factor\n"
         "materials:\n"
         "  wall: {type: lambertian, reflectance: 0.5}\n"
         "  glazing: {type: glass, transmittance: 0.7}\n"
         "geometry:\n"
         "  rooms:\n"
         "    - name: room\n"
         "      size: [4, 5, 3]\n"
         "      materials: {floor: wall, ceiling: wall, walls: wall}\n"
         "      windows: [{name: win, wall: south, width: 2, height: 1.2, sill: 1.0, offset: 1.0, material: glazing}]\n"
         "sensors:\n"
         "  grids: [{name: floor, room: room, height: 0.8, spacing: 0.5}]\n"
         "simulation: {photons_per_bin: 300, ground_reflectance: " +
         std::to_string(ground_reflectance) + ", basis: " + basis + "}\n";
}

SimulationPlan plan_of(double ground_reflectance, const std::string& basis = "tregenza") {
  return SimulationPlan::of(project::load_project_from_string(project_text(ground_reflectance, basis), "plan.yaml"));
}

TEST(PhotonSkyPlan, TheSkySourcesCarryRatiosAndTheSunBinsDoNot) {
  const SimulationPlan plan = plan_of(0.2);
  ASSERT_TRUE(plan.sky_tracing.sky_ratios);
  const RadianceMatrix df_sky = plan.daylight_factor_sky();
  EXPECT_EQ(plan.sky_tracing.sky_ratios->bins(), df_sky.rows());
  ASSERT_EQ(plan.sky_estimating.photon_sky_bin_radiance_rgb.size(), df_sky.rows());
  for (std::size_t p = 0; p < df_sky.rows(); ++p)
    EXPECT_EQ(plan.sky_estimating.photon_sky_bin_radiance_rgb[p].y, double(df_sky.at(p, 0, 1))) << "bin " << p;
  // A photon emitted toward a bin's own mean direction reads about its mean: the ratio is near 1.
  EXPECT_NEAR(plan.sky_tracing.sky_ratios->ratio(145, {0, 0, 1}), 1.0, 0.01);  // the zenith cap
  // The ground: 1 up to the float vector's rounding, and its code exactly SkyRatioOne.
  EXPECT_EQ(engine::Photon::sky_ratio_code_of(plan.sky_tracing.sky_ratios->ratio(0, {0.3, 0, -0.9})),
            engine::SkyRatioOne);
  EXPECT_FALSE(plan.sun_tracing.sky_ratios);
  EXPECT_TRUE(plan.sun_estimating.photon_sky_bin_radiance_rgb.empty());
}

TEST(PhotonSkyPlan, TheRatiosKeyFollowsTheShapeAndTheBasisNotTheGround) {
  const std::string key = plan_of(0.2).sky_tracing.sky_ratios->key();
  EXPECT_EQ(plan_of(0.0).sky_tracing.sky_ratios->key(), key);
  EXPECT_EQ(plan_of(0.5).sky_tracing.sky_ratios->key(), key);
  EXPECT_NE(plan_of(0.2, "reinhart:2").sky_tracing.sky_ratios->key(), key);
  // The bin radiances (in the coefficients' key) do follow the ground.
  EXPECT_NE(plan_of(0.5).sky_estimating.photon_sky_bin_radiance_rgb[0].x,
            plan_of(0.2).sky_estimating.photon_sky_bin_radiance_rgb[0].x);
}

}  // namespace
}  // namespace dayphoton::study
