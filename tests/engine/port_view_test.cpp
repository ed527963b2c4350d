// PortView (engine/port_view.h): a cone it rules out must hold no ray with a non-zero sky
// transmittance, and a cone that reaches a port must never be ruled out; it must also rule
// out most cones that plainly miss the window (else it saves nothing).
//   - random cones in the reference office: every ruled-out cone's rays (its axis, 8 points
//     on its rim, 32 random directions inside) all have zero sky_transmittance;
//   - cones aimed just outside the window's outline: one whose rim reaches 1e-3 of its
//     half-angle past the edge is kept, one of half the angular distance is ruled out;
//   - an interior glazed partition (a non-port surface that transmits straight) widens the
//     margin to MaxShadowRayCrossings crossings, and the results stay sound.
// Seeds are fixed, so every outcome is deterministic.
#include "dayphoton/engine/port_view.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

std::vector<Material> materials_of(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

/// Unit vector at angle `theta` from `axis`, at azimuth `phi` about it.
Vec3 in_cone(const Vec3& axis, double theta, double phi) {
  const Vec3 helper = std::fabs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 t1 = normalize(cross(axis, helper)), t2 = cross(axis, t1);
  return normalize(axis * std::cos(theta) + (t1 * std::cos(phi) + t2 * std::sin(phi)) * std::sin(theta));
}

bool any_light(const Scene& scene, const std::vector<Material>& materials, const Vec3& origin, const Vec3& w) {
  const Vec3 t = sky_transmittance(scene, materials, origin, w);
  return t.x != 0 || t.y != 0 || t.z != 0;
}

/// Random cones from random points of the room: the ruled-out ones hold no light, and the
/// share ruled out is returned.
double check_random_cones(const Scene& scene, const std::vector<Material>& materials, double pad_m,
                          double half_angle, int cones) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int ruled_out = 0;
  for (int c = 0; c < cones; ++c) {
    const Vec3 origin{0.05 + 5.9 * u(rng), 0.05 + 7.9 * u(rng), 0.05 + 2.9 * u(rng)};
    const double z = 1 - 2 * u(rng), phi = 2 * Pi * u(rng), s = std::sqrt(1 - z * z);
    const Vec3 axis{s * std::cos(phi), s * std::sin(phi), z};
    const PortView view(scene, origin, pad_m);
    if (view.may_cross_port(axis, half_angle)) continue;
    ++ruled_out;
    EXPECT_FALSE(any_light(scene, materials, origin, axis));
    for (int k = 0; k < 8; ++k)
      EXPECT_FALSE(any_light(scene, materials, origin, in_cone(axis, half_angle, 2 * Pi * k / 8)));
    for (int k = 0; k < 32; ++k)
      EXPECT_FALSE(any_light(scene, materials, origin, in_cone(axis, half_angle * std::sqrt(u(rng)), 2 * Pi * u(rng))));
  }
  return double(ruled_out) / cones;
}

TEST(PortView, RuledOutConesHoldNoLightInTheOffice) {
  const SceneDescription d = test::office_room();
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = materials_of(d);
  const double pad_m = port_view_pad_m(scene, materials);
  EXPECT_LT(pad_m, scene.ray_epsilon_m());  // nothing but the window transmits
  // The window (4 x 1.5 m in a 6 x 8 x 3 m room) covers well under a quarter of the sphere
  // of directions from almost every point: most sun-sized cones miss it.
  EXPECT_GT(check_random_cones(scene, materials, pad_m, 0.00465, 4000), 0.7);
  EXPECT_GT(check_random_cones(scene, materials, pad_m, 0.1, 2000), 0.5);
}

TEST(PortView, ConesGrazingTheWindowOutline) {
  const SceneDescription d = test::office_room();
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = materials_of(d);
  const double pad_m = port_view_pad_m(scene, materials);
  // The window is x in [1, 5], z in [0.9, 2.4] at y = 0: targets 2 cm beyond the middle of
  // each edge, the edge's mid-point and its end points.
  struct Edge {
    Vec3 target, middle, a, b;
  };
  const Edge edges[] = {{{0.98, 0, 1.65}, {1, 0, 1.65}, {1, 0, 0.9}, {1, 0, 2.4}},
                        {{5.02, 0, 1.65}, {5, 0, 1.65}, {5, 0, 0.9}, {5, 0, 2.4}},
                        {{3, 0, 0.88}, {3, 0, 0.9}, {1, 0, 0.9}, {5, 0, 0.9}},
                        {{3, 0, 2.42}, {3, 0, 2.4}, {1, 0, 2.4}, {5, 0, 2.4}}};
  for (const Vec3& origin : {Vec3{3, 4, 0.8}, Vec3{0.5, 1, 2.2}, Vec3{5.5, 0.3, 1.2}, Vec3{3, 7.5, 2.9}}) {
    const PortView view(scene, origin, pad_m);
    for (const Edge& e : edges) {
      const Vec3 axis = normalize(e.target - origin);
      // A cone reaching just past the edge's mid-point holds rays through the window.
      const double to_middle = std::acos(std::clamp(dot(axis, normalize(e.middle - origin)), -1.0, 1.0));
      EXPECT_TRUE(view.may_cross_port(axis, to_middle * (1 + 1e-3)));
      EXPECT_TRUE(any_light(scene, materials, origin, normalize(e.middle * 0.999 + Vec3{3, 0, 1.65} * 0.001 - origin)));
      // One that stays on the far side of the plane through the origin and the edge misses
      // the whole (convex) window: it must be ruled out.
      const double to_plane = std::asin(std::fabs(dot(axis, normalize(cross(e.a - origin, e.b - origin)))));
      EXPECT_FALSE(view.may_cross_port(axis, 0.5 * to_plane));
    }
  }
}

TEST(PortView, InteriorGlazingWidensTheMarginAndStaysSound) {
  SceneDescription d = test::office_room();
  // A glazed partition across the room at y = 4 (an ordinary surface, not a port).
  const int glass = test::add_material(d, "partition_glass", MaterialType::Glass, 0.0);
  test::add_surface(d, "partition", glass, {{0, 4, 0}, {6, 4, 0}, {6, 4, 3}, {0, 4, 3}});
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = materials_of(d);
  ASSERT_TRUE(has_straight_transmitting_non_port(scene, materials));
  const double pad_m = port_view_pad_m(scene, materials);
  EXPECT_GT(pad_m, 2.0 * MaxShadowRayCrossings * scene.ray_epsilon_m());
  EXPECT_GT(check_random_cones(scene, materials, pad_m, 0.00465, 2000), 0.5);
}

TEST(PortView, TheUsualHalfAngleChangesNoAnswer) {
  // A view computes the trigonometry of its usual half-angle once; the answers must be those
  // of a view that computes it per query, at that half-angle and at others, for directions
  // all around (random origins in the office), with and without the interior-glazing pad.
  const SceneDescription d = test::office_room();
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = materials_of(d);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const double sun = 0.2665 * Pi / 180;
  int crossing = 0, missing = 0;
  for (double pad : {port_view_pad_m(scene, materials), 0.05})
    for (int c = 0; c < 200; ++c) {
      const Vec3 origin{0.05 + 5.9 * u(rng), 0.05 + 7.9 * u(rng), 0.05 + 2.9 * u(rng)};
      const PortView plain(scene, origin, pad, -1.0);  // never asked at -1: computes per query
      const PortView single(scene, origin, pad), disc(scene, origin, pad, sun);
      for (int k = 0; k < 50; ++k) {
        const double z = 1 - 2 * u(rng), phi = 2 * Pi * u(rng), s = std::sqrt(1 - z * z);
        const Vec3 w{s * std::cos(phi), s * std::sin(phi), z};
        for (double half : {0.0, sun, 0.1}) {
          const bool want = plain.may_cross_port(w, half);
          ASSERT_EQ(single.may_cross_port(w, half), want) << c << ' ' << k << ' ' << half;
          ASSERT_EQ(disc.may_cross_port(w, half), want) << c << ' ' << k << ' ' << half;
          (want ? crossing : missing) += 1;
        }
      }
    }
  EXPECT_GT(crossing, 100);
  EXPECT_GT(missing, 100);
}

}  // namespace
}  // namespace dayphoton::engine
