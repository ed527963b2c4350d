// Receiver-plane sensors next to a cut (plane_cuts.h, "Sensors next to a cut"): estimated by
// final gather inside their grid (GridPhotons::set_near_cut_gather, daylight_coefficients.h).
// On a traced room with a column crossing the work plane, the gathered rows are bit for bit
// the final gather of the same points as a point set (their photon part and its variance), the
// other rows the plane's estimate, the direct part the same shadow rays, and a block of rows
// (an MPI rank's, sensor_range.h) that grid's rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/final_gather.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/plane_cuts.h"
#include "dayphoton/sky/patch_basis.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

/// A 4 x 3 x 2.5 m room, a 2 m window in its south wall (y = 0), and a 0.4 m column at
/// x 1.8-2.2, y 1.3-1.7 from floor to ceiling.
SceneDescription column_room() {
  SceneDescription d;
  const int floor = test::add_material(d, "floor", MaterialType::Lambertian, 0.3);
  const int wall = test::add_material(d, "wall", MaterialType::Lambertian, 0.5);
  const int ceiling = test::add_material(d, "ceiling", MaterialType::Lambertian, 0.7);
  const int glass = test::add_material(d, "glazing", MaterialType::Glass, 0.0);
  test::add_surface(d, "floor", floor, {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}});
  test::add_surface(d, "ceiling", ceiling, {{0, 0, 2.5}, {0, 3, 2.5}, {4, 3, 2.5}, {4, 0, 2.5}});
  test::add_surface(d, "west", wall, {{0, 0, 0}, {0, 3, 0}, {0, 3, 2.5}, {0, 0, 2.5}});
  test::add_surface(d, "east", wall, {{4, 0, 0}, {4, 0, 2.5}, {4, 3, 2.5}, {4, 3, 0}});
  test::add_surface(d, "north", wall, {{0, 3, 0}, {4, 3, 0}, {4, 3, 2.5}, {0, 3, 2.5}});
  test::add_surface(d, "sill", wall, {{0, 0, 0}, {0, 0, 0.8}, {4, 0, 0.8}, {4, 0, 0}});
  test::add_surface(d, "head", wall, {{0, 0, 2.2}, {0, 0, 2.5}, {4, 0, 2.5}, {4, 0, 2.2}});
  test::add_surface(d, "jamb_w", wall, {{0, 0, 0.8}, {0, 0, 2.2}, {1, 0, 2.2}, {1, 0, 0.8}});
  test::add_surface(d, "jamb_e", wall, {{3, 0, 0.8}, {3, 0, 2.2}, {4, 0, 2.2}, {4, 0, 0.8}});
  test::add_surface(d, "window", glass, {{1, 0, 0.8}, {1, 0, 2.2}, {3, 0, 2.2}, {3, 0, 0.8}}, true);
  // The column's four faces, facing out.
  test::add_surface(d, "column_s", wall, {{1.8, 1.3, 0}, {2.2, 1.3, 0}, {2.2, 1.3, 2.5}, {1.8, 1.3, 2.5}});
  test::add_surface(d, "column_e", wall, {{2.2, 1.3, 0}, {2.2, 1.7, 0}, {2.2, 1.7, 2.5}, {2.2, 1.3, 2.5}});
  test::add_surface(d, "column_n", wall, {{2.2, 1.7, 0}, {1.8, 1.7, 0}, {1.8, 1.7, 2.5}, {2.2, 1.7, 2.5}});
  test::add_surface(d, "column_w", wall, {{1.8, 1.7, 0}, {1.8, 1.3, 0}, {1.8, 1.3, 2.5}, {1.8, 1.7, 2.5}});
  return d;
}

std::vector<Material> models_of(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

TEST(NearCutGather, SensorsNextToAColumnAreGatheredTheOthersKeepThePlane) {
  const SceneDescription d = column_room();
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  ReceiverPlane plane(0.8, true, {{0, 0}, {4, 0}, {4, 3}, {0, 3}});
  plane.set_interior_cuts(interior_plane_cuts(scene, plane));
  ASSERT_EQ(plane.interior_cuts().size() % 4, 0u);
  ASSERT_FALSE(plane.interior_cuts().empty());
  // A row of sensors across the column's front and back, 0.1 m to 0.5 m from it, and one 0.1 m
  // from the west wall (walls are not cuts).
  const std::vector<SensorPoint> sensors = {
      {{2.0, 1.2, 0.8}, {0, 0, 1}},  {{2.0, 1.0, 0.8}, {0, 0, 1}}, {{2.0, 0.8, 0.8}, {0, 0, 1}},
      {{2.0, 1.8, 0.8}, {0, 0, 1}},  {{2.0, 2.2, 0.8}, {0, 0, 1}}, {{2.3, 1.5, 0.8}, {0, 0, 1}},
      {{0.1, 1.5, 0.8}, {0, 0, 1}},  {{2.25, 1.75, 0.8}, {0, 0, 1}}};
  const std::vector<std::size_t> near = sensors_near_cuts(plane, sensors);
  EXPECT_EQ(near, (std::vector<std::size_t>{0, 3, 5, 7}));  // 0.1, 0.1, 0.1 and 0.071 m; 0.3 m is not nearer
  EXPECT_EQ(sensors_near_cuts(plane, sensors, {3, 6}), (std::vector<std::size_t>{3, 5}));

  TracingOptions o;
  o.photons_per_source = 400;
  o.keep_surface_photons = true;
  o.store_direct_on_surfaces = true;
  const TracedPhotons traced = trace_photons(scene, materials, sources, {plane}, o);
  CoefficientOptions co;
  co.density.bandwidth = 40;
  co.direct.samples_per_source = 4;
  co.gather.rays_per_sensor = 64;
  const GridPhotons on_plane = GridPhotons::for_plane(plane, traced.planes[0], sources.size());
  GridPhotons mixed = GridPhotons::for_plane(plane, traced.planes[0], sources.size());
  auto gather = std::make_shared<const GridPhotons>(GridPhotons::for_gather(traced.surface, sources.size()));
  mixed.set_near_cut_gather(gather);
  EXPECT_THROW(mixed.set_near_cut_gather(std::make_shared<const GridPhotons>(on_plane)), std::invalid_argument);
  EXPECT_THROW(GridPhotons(*gather).set_near_cut_gather(gather), std::invalid_argument);

  const DaylightCoefficients plane_only = daylight_coefficients(scene, materials, sources, on_plane, sensors, co);
  const DaylightCoefficients both = daylight_coefficients(scene, materials, sources, mixed, sensors, co);
  // The same points as a point set: a final gather at every sensor.
  const GatheredCoefficients points =
      gather_photon_coefficients(scene, materials, sources, gather->all(), sensors, co.gather, &gather->groups());
  const std::size_t n = sources.size();
  double gathered_total = 0, plane_total = 0;
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    const bool gathered = std::find(near.begin(), near.end(), s) != near.end();
    for (std::size_t p = 0; p < n; ++p) {
      const std::size_t i = s * n + p;
      ASSERT_TRUE(same_bits(both.direct[i], plane_only.direct[i])) << s << " " << p;
      ASSERT_EQ(both.direct_variance[i], plane_only.direct_variance[i]);
      if (gathered) {
        ASSERT_TRUE(same_bits(both.caustic[i], points.caustic[i])) << s << " " << p;
        ASSERT_TRUE(same_bits(both.global[i], points.global[i])) << s << " " << p;
        ASSERT_EQ(both.photon_variance[i], points.variance[i]) << s << " " << p;
        gathered_total += luminance_of(both.global[i]);
        plane_total += luminance_of(plane_only.global[i]);
      } else {
        ASSERT_TRUE(same_bits(both.caustic[i], plane_only.caustic[i])) << s << " " << p;
        ASSERT_TRUE(same_bits(both.global[i], plane_only.global[i])) << s << " " << p;
        ASSERT_EQ(both.photon_variance[i], plane_only.photon_variance[i]) << s << " " << p;
      }
    }
  }
  EXPECT_GT(gathered_total, 0.0);
  EXPECT_NE(gathered_total, plane_total);  // the rows did change
  // A block of rows (sensor_range.h) is those rows of the whole grid.
  const DaylightCoefficients block = daylight_coefficients(scene, materials, sources, mixed, sensors, co, {2, 6});
  ASSERT_EQ(block.sensors, 4u);
  for (std::size_t r = 0; r < block.sensors; ++r)
    for (std::size_t p = 0; p < n; ++p) {
      const std::size_t i = r * n + p, whole = (r + 2) * n + p;
      ASSERT_TRUE(same_bits(block.global[i], both.global[whole])) << r << " " << p;
      ASSERT_TRUE(same_bits(block.caustic[i], both.caustic[whole])) << r << " " << p;
      ASSERT_EQ(block.photon_variance[i], both.photon_variance[whole]) << r << " " << p;
    }
  // A gather at some sensors is that of the whole set's rows (seeded by the sensor's index).
  const GatheredCoefficients at = gather_photon_coefficients_at(scene, materials, sources, gather->all(), sensors,
                                                                co.gather, &gather->groups(), {7, 3});
  for (std::size_t p = 0; p < n; ++p) {
    EXPECT_TRUE(same_bits(at.global[p], points.global[7 * n + p]));
    EXPECT_TRUE(same_bits(at.global[n + p], points.global[3 * n + p]));
    EXPECT_EQ(at.fixed_photon_variance[p], points.fixed_photon_variance[7 * n + p]);
  }
  EXPECT_THROW(gather_photon_coefficients_at(scene, materials, sources, gather->all(), sensors, co.gather,
                                             &gather->groups(), {8}),
               std::invalid_argument);
}

// Sensors exactly NearCutGather_m from a cut, on either side of a 0.4 m column's faces at x
// 2.8 and 3.2 (sensors at 2.5 and 3.5, whose differences round 0.3 down on one side and up on
// the other), are both out; 1 mm nearer both are in (NearCutMargin_m).
TEST(NearCutGather, SensorsExactlyAtTheDistanceAreOutOnEitherSide) {
  ReceiverPlane plane(0.8, true, {{0, 0}, {6, 0}, {6, 6}, {0, 6}});
  plane.set_interior_cuts({{{2.8, 2.8}, {2.8, 3.2}}, {{2.8, 3.2}, {3.2, 3.2}}, {{3.2, 3.2}, {3.2, 2.8}},
                           {{3.2, 2.8}, {2.8, 2.8}}});
  auto at = [](double x) { return SensorPoint{{x, 3.0, 0.8}, {0, 0, 1}}; };
  EXPECT_TRUE(sensors_near_cuts(plane, {at(2.5), at(3.5)}).empty());
  EXPECT_EQ(sensors_near_cuts(plane, {at(2.501), at(3.499)}), (std::vector<std::size_t>{0, 1}));
}

// A sensor within OnCut_m of an opaque cut lies on it (study/placement_check.h refuses it):
// on the column's west face and at its corner; 2 mm off the face it does not. A glass pane
// crossing the plane at x = 3 counts only for the cuts of every surface, not the opaque ones.
TEST(NearCutGather, SensorsOnAnOpaqueCutAreOnIt) {
  SceneDescription d = column_room();
  const int glass = test::add_material(d, "pane", MaterialType::Glass, 0.0);
  test::add_surface(d, "pane", glass, {{3, 0.5, 0}, {3, 2.5, 0}, {3, 2.5, 2.5}, {3, 0.5, 2.5}});
  const Scene scene = Scene::build(d);
  ReceiverPlane plane(0.8, true, {{0, 0}, {4, 0}, {4, 3}, {0, 3}});
  auto at = [](double x, double y) { return SensorPoint{{x, y, 0.8}, {0, 0, 1}}; };
  const std::vector<SensorPoint> sensors = {at(1.8, 1.5), at(1.8, 1.3), at(1.798, 1.5), at(3, 1.5), at(1, 1)};
  plane.set_interior_cuts(interior_plane_cuts(scene, plane, true));
  EXPECT_EQ(sensors_on_cuts(plane, sensors), (std::vector<std::size_t>{0, 1}));
  plane.set_interior_cuts(interior_plane_cuts(scene, plane));
  EXPECT_EQ(sensors_on_cuts(plane, sensors), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(sensors_near_cuts(plane, sensors), (std::vector<std::size_t>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace dayphoton::engine
