// PortBound rules a port out only for rays that cross none of its triangles: against a
// Moller-Trumbore intersection written here (double precision, t > 0), over rays aimed at
// random points of the port, at its vertices and just beyond its edges, and at random
// directions, from inside and outside the room, on the office window and on a tilted
// concave L-shaped port. The sphere must also rule out some rays (else it saves nothing).
#include "dayphoton/engine/port_bound.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "dayphoton/engine/scene.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

bool crosses(const Port& port, const Vec3& origin, const Vec3& w) {
  for (const std::array<Vec3, 3>& tri : port.triangles) {
    const Vec3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const Vec3 pv = cross(w, e2);
    const double det = dot(e1, pv);
    if (det == 0.0) continue;
    const Vec3 tv = origin - tri[0];
    const double u = dot(tv, pv) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Vec3 qv = cross(tv, e1);
    const double v = dot(w, qv) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    if (dot(e2, qv) / det > 0.0) return true;
  }
  return false;
}

void check_ports(const PortSet& ports, std::uint64_t seed) {
  const std::vector<PortBound> bounds = port_bounds(ports);
  ASSERT_EQ(bounds.size(), ports.size());
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), box(-6.0, 10.0), jitter(-0.05, 0.05);
  int crossing = 0, ruled_out = 0;
  for (std::size_t j = 0; j < ports.size(); ++j) {
    const Port& port = ports[j];
    for (int i = 0; i < 20000; ++i) {
      const Vec3 origin{box(rng), box(rng), box(rng)};
      Vec3 w;
      const int kind = i % 4;
      if (kind == 3) {  // any direction
        w = normalize(Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5});
      } else {
        Vec3 target;
        if (kind == 0) {
          target = ports.sample(j, u(rng), u(rng)).position;  // a point of the port
        } else {
          const std::array<Vec3, 3>& tri = port.triangles[static_cast<std::size_t>(i) % port.triangles.size()];
          target = tri[static_cast<std::size_t>(i / 4) % 3];  // a vertex, or just beyond it
          if (kind == 2) target = target + Vec3{jitter(rng), jitter(rng), jitter(rng)};
        }
        w = target - origin;
        if (i % 8 < 4) w = normalize(w);  // unit and non-unit directions
      }
      const bool hit = crosses(port, origin, w);
      const bool may = bounds[j].may_cross(origin, w);
      ASSERT_TRUE(may || !hit) << "port " << j << " ray " << i;
      crossing += hit;
      ruled_out += !may;
    }
  }
  EXPECT_GT(crossing, 1000);
  EXPECT_GT(ruled_out, 1000);
}

TEST(PortBound, NeverRulesOutACrossingOfTheOfficeWindow) {
  const Scene scene = Scene::build(test::office_room());
  check_ports(scene.ports(), 1);
}

TEST(PortBound, NeverRulesOutACrossingOfATiltedConcavePort) {
  const Vec3 O{1, 2, 3};
  const Vec3 e1 = normalize(Vec3(1, 1, 0));
  const Vec3 e2 = normalize(Vec3(-1, 1, 1));
  auto P = [&](double a, double b) { return O + e1 * a + e2 * b; };
  SceneDescription d;
  test::add_material(d, "glass", MaterialType::Glass, 0);
  test::add_surface(d, "L", 0, {P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2)}, true);
  const Scene scene = Scene::build(d);
  check_ports(scene.ports(), 2);
}

}  // namespace
}  // namespace dayphoton::engine
