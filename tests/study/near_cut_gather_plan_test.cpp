// A receiver plane's sensors next to a cut (engine/plane_cuts.h, "Sensors next to a cut") in the
// study: the case layout counts them and keeps the surface photons with their direct ones for
// their gather (simulation_plan.h), the cache keys change only for a grid that has them
// (cache_keys.h), and the accuracy rounds leave them out of their measure (accuracy_policy.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <string>
#include <vector>

#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/plane_cuts.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/accuracy_policy.h"
#include "dayphoton/study/accuracy_rounds.h"
#include "dayphoton/study/cache_keys.h"
#include "dayphoton/study/simulation_plan.h"
#include "placement_project_text.h"

namespace dayphoton::study {
namespace {

/// A 6 x 8 m room, a grid every 0.5 m from 0.5 m, and (with `column`) a 0.3 m column at x
/// 2.6-2.9, y 3.6-3.9: the four sensors around it, x 2.5 or 3, y 3.5 or 4, lie 0.141 m from its
/// corners; the next ones 0.6 m or more.
std::string project_text(bool column, const std::string& point_estimate) {
  std::string text = PlacementHead + "study: daylight_factor\n" + PlacementOffice;
  if (column) text += "  boxes:\n    - {name: column, origin: [2.6, 3.6, 0], size: [0.3, 0.3, 3], material: walls}\n";
  text += "sensors:\n  grids:\n    - {name: workplane, room: office, height: 0.8, spacing: 0.5, inset: 0.5}\n";
  text += "simulation: {point_estimate: " + point_estimate + "}\n";
  return text;
}

struct Case {
  project::Project project;
  SceneDescription description;
  CaseLayout layout;
};

Case case_of(bool column, const std::string& point_estimate = "gather") {
  Case c{project::load_project_from_string(project_text(column, point_estimate), "near_cut.yaml"), {}, {}};
  c.description = project::build_scene_description(c.project);
  const engine::Scene scene = engine::Scene::build(c.description);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : c.description.materials) materials.push_back(engine::Material::from_spec(m));
  c.layout = CaseLayout::of(c.description.grids, scene, materials);
  return c;
}

TEST(NearCutGatherPlan, TheLayoutCountsTheSensorsAndKeepsTheSurfacePhotonsForThem) {
  const Case with = case_of(true, "surface");
  ASSERT_EQ(with.layout.near_cut_sensors.size(), 1u);
  EXPECT_EQ(with.layout.near_cut_sensors[0], 4u);
  EXPECT_TRUE(with.layout.gathers_near_cuts());
  EXPECT_TRUE(with.layout.grid_gathers_near_cuts(0));
  EXPECT_TRUE(with.layout.keep_surface_photons);
  // The gather reads the direct hits on surfaces, with point_estimate: surface too.
  const SimulationPlan plan = SimulationPlan::of(with.project);
  EXPECT_TRUE(plan.tracing_for(plan.sky_tracing, with.layout).store_direct_on_surfaces);
  EXPECT_TRUE(plan.tracing_for(plan.sun_tracing, with.layout).keep_surface_photons);

  const Case without = case_of(false);
  ASSERT_EQ(without.layout.near_cut_sensors.size(), 1u);
  EXPECT_EQ(without.layout.near_cut_sensors[0], 0u);
  EXPECT_FALSE(without.layout.gathers_near_cuts());
  EXPECT_FALSE(without.layout.keep_surface_photons);
  const SimulationPlan plain = SimulationPlan::of(without.project);
  EXPECT_FALSE(plain.tracing_for(plain.sky_tracing, without.layout).store_direct_on_surfaces);
}

// The gather keeps every surface photon of the case (2-4 times its memory), so a case of
// planar grids alone gathers its sensors next to a cut only where some grid has at least
// NearCutGatherMinShare (1 %) of its sensors there; once the photons are kept (that, or a grid
// off the plane), every such sensor is gathered. Closed-form cases of the rule.
TEST(NearCutGatherPlan, TheSurfacePhotonsAreKeptOnlyWhereEnoughSensorsAreNextToACut) {
  using V = std::vector<bool>;
  EXPECT_EQ(near_cut_gathered({1}, {200}, false), V{false});   // 0.5 % of one grid
  EXPECT_EQ(near_cut_gathered({2}, {200}, false), V{true});    // 1 %
  EXPECT_EQ(near_cut_gathered({1}, {200}, true), V{true});     // kept for a wall grid anyway
  EXPECT_EQ(near_cut_gathered({0}, {200}, true), V{false});    // nothing next to a cut
  EXPECT_EQ(near_cut_gathered({1, 5}, {200, 200}, false), (V{true, true}));  // the second keeps them
  EXPECT_EQ(near_cut_gathered({1, 0}, {200, 10}, false), (V{false, false}));
  EXPECT_EQ(near_cut_gathered({69}, {9984}, false), V{false});  // the open-plan bench's columns: 0.7 %
  EXPECT_EQ(near_cut_gathered({18}, {1196}, false), V{true});   // one column, a grid every 0.2 m: 1.5 %
}

TEST(NearCutGatherPlan, CacheKeysChangeOnlyForAGridWithSensorsNextToACut) {
  const Case c = case_of(true);
  const SimulationPlan plan = SimulationPlan::of(c.project);
  const SensorGrid& grid = c.description.grids[0];
  const std::vector<std::string> photons = {"a", "b"};
  const std::string none = coefficients_key(photons, grid, plan.sky_estimating);
  EXPECT_EQ(coefficients_key(photons, grid, plan.sky_estimating, 0), none);
  EXPECT_NE(coefficients_key(photons, grid, plan.sky_estimating, 4), none);
  EXPECT_NE(coefficients_key(photons, grid, plan.sky_estimating, 4), coefficients_key(photons, grid, plan.sky_estimating, 5));
  const std::string sun = sun_coefficients_key(photons, 0.01, grid, plan.sun_estimating);
  EXPECT_EQ(sun_coefficients_key(photons, 0.01, grid, plan.sun_estimating, 0), sun);
  EXPECT_NE(sun_coefficients_key(photons, 0.01, grid, plan.sun_estimating, 4), sun);
}

TEST(NearCutGatherPlan, TheRoundsMeasureLeavesTheGatheredRowsOut) {
  const Case c = case_of(true);
  const std::vector<SensorPoint>& points = c.description.grids[0].points;
  const std::vector<std::size_t> rows =
      near_cut_rows(c.layout.planes, c.layout.plane_of_grid, &c.layout.near_cut_sensors, points, 0);
  ASSERT_EQ(rows.size(), 4u);
  for (std::size_t i : rows)
    EXPECT_LT(engine::distance_to_interior_cut_m(c.layout.planes[0], points[i].position.x, points[i].position.y),
              engine::NearCutGather_m);
  EXPECT_EQ(near_cut_count(c.layout.plane_of_grid, &c.layout.near_cut_sensors, 0), 4u);
  EXPECT_EQ(near_cut_count(c.layout.plane_of_grid, nullptr, 0), 0u);
  EXPECT_TRUE(near_cut_rows(c.layout.planes, c.layout.plane_of_grid, nullptr, points, 0).empty());
  EXPECT_EQ(near_cut_count({-1}, &c.layout.near_cut_sensors, 0), 0u);

  // Every plane row at 1 % relative error, the gathered ones at 5 % and 10 %: the measure's
  // percentile is over the plane rows (1 %), and the note names the gathered rows' largest error.
  std::vector<double> df(points.size(), 2.0), se(points.size(), 0.02);
  for (std::size_t i : rows) se[i] = 0.1;
  df[rows[1]] = 1.0;  // 10 %
  std::vector<double> measured = df;
  NearCutReached reached = take_out_near_cut_rows(rows, measured, se);
  EXPECT_EQ(reached.sensors, 4u);
  EXPECT_NEAR(reached.largest_percent, 10.0, 1e-12);
  for (std::size_t i : rows) EXPECT_EQ(measured[i], 0.0);
  EXPECT_NEAR(percentile_relative_stderr_percent(measured, se, AccuracyPercentile), 1.0, 1e-12);
  // The verdict states them apart: during the photon rounds (which do not gather them) their
  // count; after their gather rounds the largest error, the rays they reached and, above the
  // target, the gather stop.
  EXPECT_EQ(near_cut_note(reached, 1.0), "; 4 sensors next to a cut, gathered after the photon rounds");
  NearCutReached in_round = reached;  // a round that gathers them (a gathered grid's map)
  in_round.gather_rays = 1024;
  EXPECT_EQ(near_cut_note(in_round, 1.0), "; 4 sensors next to a cut gathered, largest 10 %");
  // A round gathers them only where a gathered grid builds the gather map anyway.
  EXPECT_FALSE(near_cut_gathered_in_rounds({0}, true));
  EXPECT_FALSE(near_cut_gathered_in_rounds({0, -1}, false));  // the surface estimate: no gather map
  EXPECT_TRUE(near_cut_gathered_in_rounds({0, -1}, true));
  reached.gather_rays = 4096;
  reached.rounds = 2;
  reached.stop_reason = "gather photon part";
  EXPECT_EQ(near_cut_note(reached, 1.0), "; 4 sensors next to a cut gathered, largest 10 % at 4096 gather rays (2 "
                                         "gather round(s)) > target 1 %: gather photon part");
  reached.rounds = 0;
  reached.stop_reason = "target met";
  EXPECT_EQ(near_cut_note(reached, 10.0), "; 4 sensors next to a cut gathered, largest 10 %");
  EXPECT_EQ(take_out_near_cut_rows({}, measured, se).sensors, 0u);
  EXPECT_EQ(near_cut_note(NearCutReached{}, 1.0), "");
}

// After the rounds the sensors next to a cut are gathered (the gather rounds splice their rows
// into the grid's coefficients): their photon part on the DF sky must be the gather's own on
// that sky (engine/final_gather.h, "The continuous sky"; it differs from the gather's basis sum),
// not the plane's estimate the photon rounds left in those rows, nor the basis sum; every other
// row the estimate with the sky ratios (which differs from its basis sum too); no row left on
// the basis.
TEST(NearCutGatherPlan, TheGatheredRowsPhotonPartOnTheSkyIsTheGathersOwn) {
  const Case c = case_of(true);
  const SimulationPlan plan = SimulationPlan::of(c.project);
  const engine::Scene scene = engine::Scene::build(c.description);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : c.description.materials) materials.push_back(engine::Material::from_spec(m));
  const engine::SourceSet sources = engine::SourceSet::sky_bins(plan.basis);
  const RadianceMatrix overcast = plan.daylight_factor_sky();
  AccuracyCase a;
  a.scene = &scene;
  a.materials = &materials;
  a.sources = &sources;
  a.planes = &c.layout.planes;
  a.plane_of_grid = &c.layout.plane_of_grid;
  a.near_cut_sensors = &c.layout.near_cut_sensors;
  a.grids = &c.description.grids;
  a.tracing = plan.tracing_for(plan.sky_tracing, c.layout);
  a.tracing.photons_per_source = 500;
  a.estimating = plan.sky_estimating;
  a.estimating.gather.rays_per_sensor = 16;
  a.overcast_vector = &overcast;
  a.horizontal_illuminance_lux = plan.overcast_horizontal_lux;
  AccuracyGoal goal;
  goal.target_percent = 5.0;
  const AccuracyResult r = run_accuracy_rounds(a, goal, [](const std::string&) {});
  const engine::DaylightCoefficients& dc = r.coefficients.at(0);
  ASSERT_EQ(dc.photon_on_sky.irradiance.size(), dc.sensors);
  const std::vector<std::size_t> rows =
      near_cut_rows(c.layout.planes, c.layout.plane_of_grid, &c.layout.near_cut_sensors, c.description.grids[0].points, 0);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(dc.photon_on_sky.basis_rows, 0u);
  const NearCutEstimate& near = r.near_cut.at(0);
  ASSERT_EQ(near.rows, rows);
  ASSERT_EQ(near.coefficients.photon_on_sky.irradiance.size(), rows.size());
  const std::vector<Vec3>& radiance = a.estimating.photon_sky_bin_radiance_rgb;
  auto basis_sum = [&](std::size_t s) {
    double e = 0;
    for (std::size_t p = 0; p < dc.sources; ++p)
      e += engine::luminance_of(mul(dc.caustic[s * dc.sources + p] + dc.global[s * dc.sources + p], radiance[p]));
    return e;
  };
  std::size_t differ = 0;
  for (std::size_t s = 0; s < dc.sensors; ++s) {
    const double on_sky = engine::luminance_of(dc.photon_on_sky.irradiance[s]), basis = basis_sum(s);
    ASSERT_GT(basis, 0) << "sensor " << s;
    const auto at = std::find(rows.begin(), rows.end(), s);
    if (at != rows.end()) {
      const std::size_t i = static_cast<std::size_t>(at - rows.begin());
      EXPECT_EQ(dc.photon_on_sky.irradiance[s], near.coefficients.photon_on_sky.irradiance[i]) << "sensor " << s;
      EXPECT_EQ(dc.photon_on_sky.variance[s], near.coefficients.photon_on_sky.variance[i]) << "sensor " << s;
    }
    differ += std::fabs(on_sky / basis - 1) > 1e-6;
  }
  EXPECT_EQ(differ, dc.sensors);
}

}  // namespace
}  // namespace dayphoton::study
