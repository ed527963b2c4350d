// The estimated cost of a case (case_cost.h): the model's terms against the project's sizes,
// and the sun year of the office against the sky matrix the run builds.
#include <gtest/gtest.h>

#include <string>

#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/case_cost.h"
#include "dayphoton/study/plan_policy.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/hourly_weather.h"
#include "side_lit_room.h"

namespace dayphoton::study {
namespace {

std::size_t sensors_of(const project::Project& p) {
  std::size_t n = 0;
  for (const SensorGrid& g : project::build_scene_description(p).grids) n += g.points.size();
  return n;
}

TEST(CaseCost, DaylightFactorCaseIsSceneSkyPhotonsAndSkyEstimates) {
  // A daylight-factor study: no annual terms, whatever the year says.
  const project::Project room =
      project::load_project_from_string(test::side_lit_room_yaml("[4, 5, 3]", "3", 300), "room.yaml");
  const double sensors = static_cast<double>(sensors_of(room));
  ASSERT_GT(sensors, 0);
  const double sources = 146;  // Tregenza: 145 sky patches and the ground
  const double expected = case_cost::SceneSeconds + 300 * (145 + GroundPhotonFactor) * case_cost::SkyPhotonSeconds +
                          sensors * sources * case_cost::SkyEstimateSeconds;
  EXPECT_NEAR(case_cost_seconds(room, SunYear{}), expected, 1e-12 * expected);
}

TEST(CaseCost, GrowsWithPhotonsAndSensorsAndIsEqualForVariantsOfOneSize) {
  const auto load = [](const std::string& size, int photons, const std::string& extra = "") {
    return project::load_project_from_string(test::side_lit_room_yaml(size, "3", photons) + extra, "room.yaml");
  };
  const project::Project small = load("[4, 5, 3]", 300), more_photons = load("[4, 5, 3]", 600),
                         bigger = load("[8, 5, 3]", 300);
  ASSERT_GT(sensors_of(bigger), sensors_of(small));
  const double base = case_cost_seconds(small, {});
  EXPECT_NEAR(case_cost_seconds(more_photons, {}) - base, 300 * (145 + GroundPhotonFactor) * case_cost::SkyPhotonSeconds,
              1e-9);
  EXPECT_NEAR(case_cost_seconds(bigger, {}) - base,
              double(sensors_of(bigger) - sensors_of(small)) * 146 * case_cost::SkyEstimateSeconds, 1e-9);
  // A variant that changes a material only is a case of the same size: the same estimate.
  const project::Project with_variant =
      load("[4, 5, 3]", 300, "variants:\n  - name: darker\n    materials: {walls: {type: lambertian, reflectance: 0.3}}\n");
  const std::vector<double> costs = case_costs_seconds(with_variant, {});
  ASSERT_EQ(costs.size(), 2u);
  EXPECT_EQ(costs[0], costs[1]);
  EXPECT_EQ(costs[0], base);
}

TEST(CaseCost, TheOfficeYearIsTheSunsOfItsSkyMatrix) {
  const project::Project office = project::load_project(std::string(DAYPHOTON_SOURCE_DIR) + "/projects/office/project.yaml");
  ASSERT_EQ(office.simulation.sun, project::SunMode::Bins);
  const weather::HourlyWeather weather = weather::read_hourly_weather(office.weather.path);
  const SunSite site = resolve_sun_site(office.site, weather);
  const SunYear year = sun_year_of(office, &weather, &site);
  // The suns the run traces the direct sun of, and their bins (sky_steps.cpp, annual_sun.h).
  const SkyAndSuns ss = annual_sky_and_suns(weather, site.solar, sky::PatchBasis::tregenza(),
                                            sun_excluded_sky_options(office.simulation.ground_reflectance));
  std::vector<Vec3> directions;
  for (const sky::SunRecord& s : ss.suns) directions.push_back(s.direction);
  EXPECT_EQ(year.hours, weather.records.size());
  // The records with a direct normal irradiance > 0 are a few more than the run's suns (a
  // record's direct illuminance from the Perez efficacy may be 0): within 1 %, never fewer.
  const std::size_t bins = engine::SunBins::for_suns(directions, office.simulation.sun_mf).size();
  EXPECT_GE(year.sun_hours, ss.suns.size());
  EXPECT_LE(double(year.sun_hours), 1.01 * double(ss.suns.size()));
  EXPECT_GE(year.sun_bins, bins);
  EXPECT_LE(double(year.sun_bins), 1.01 * double(bins));
  // Its one case: every term of the model, the sun's and the annual multiply's included.
  const double sensors = double(sensors_of(office));
  const double sky = case_cost_seconds(office, SunYear{});
  const double expected = sky +
                          double(year.sun_bins) * 4000 * case_cost::SunPhotonSeconds +
                          sensors * double(year.sun_bins) * case_cost::SunEstimateSeconds +
                          sensors * double(year.sun_hours) * case_cost::DirectSunSeconds +
                          sensors * double(year.hours) * case_cost::AnnualMultiplySeconds;
  EXPECT_NEAR(case_cost_seconds(office, year), expected, 1e-9 * expected);
}

}  // namespace
}  // namespace dayphoton::study
