// Test support for the photon tracer: a tessellated sphere (the furnace of seeds/000 chapter
// 6) and a brute-force light tracer that emits a distant source from a disc around the
// whole scene, WITHOUT photon ports (the "scene cube" emission of seeds/000 section 4.1.2),
// so that port emission and the direct/photon split can be checked against it.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine::test {

/// Icosphere of radius `radius_m` centred at the origin, subdivided `levels` times
/// (20 * 4^levels triangles), normals facing the centre, all with material `material`.
inline void add_inward_sphere(SceneDescription& d, int material, double radius_m, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : v) p = normalize(p);
  std::vector<std::array<int, 3>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(normalize(v[a] + v[b]));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& tri : f) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]),
                c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  for (const auto& tri : f) {
    Surface s;
    s.name = "sphere." + std::to_string(d.surfaces.size());
    s.material = material;
    // Outward winding reversed: normals face the centre.
    s.vertices = {v[tri[0]] * radius_m, v[tri[2]] * radius_m, v[tri[1]] * radius_m};
    s.location = SourceLocation{"sphere", static_cast<int>(d.surfaces.size()) + 1, 1};
    d.surfaces.push_back(std::move(s));
  }
}

/// Brute-force emission of a distant source without ports: photon i gets a direction d
/// toward the source from `sample_direction(u1, u2)` (uniform over a solid angle
/// `solid_angle_sr`), a point uniform on the disc of radius R (the scene's bounding sphere)
/// perpendicular to d, and starts outside the scene moving along -d with RGB flux
/// radiance(d) * solid_angle * pi R^2 / count. Photons are traced with trace_path
/// (zero-event photons reported as Direct when options.store_direct).
inline void brute_force_emission(const Scene& scene, const std::vector<Material>& materials,
                                 const std::vector<ReceiverPlane>& planes,
                                 const std::function<Vec3(double, double)>& sample_direction,
                                 double solid_angle_sr,
                                 const std::function<Vec3(const Vec3&)>& radiance,
                                 std::uint64_t first, std::uint64_t count, std::uint64_t total,
                                 std::uint64_t seed, const TracingOptions& options,
                                 PhotonSink& sink) {
  const Bounds3& b = scene.bounds();
  const Vec3 centre = b.center();
  const double radius = 0.5 * length(b.extent()) * 1.01 + 1e-3;
  const double flux_scale = solid_angle_sr * Pi * radius * radius / double(total);
  for (std::uint64_t i = first; i < first + count; ++i) {
    Rng emission(seed, 0, i, RandomStream::Emission);
    const Vec3 d = sample_direction(emission.uniform(), emission.uniform());
    const Vec3 helper = std::fabs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 e1 = normalize(cross(d, helper));
    const Vec3 e2 = cross(d, e1);
    const double r = radius * std::sqrt(emission.uniform());
    const double phi = 2 * Pi * emission.uniform();
    PathStart start;
    start.origin = centre + d * (2 * radius) + e1 * (r * std::cos(phi)) + e2 * (r * std::sin(phi));
    start.direction = d * -1.0;
    start.flux = radiance(d) * flux_scale;
    Rng scattering(seed, 0, i, RandomStream::Scattering);
    Rng roulette(seed, 0, i, RandomStream::Roulette);
    trace_path(scene, materials, planes, start, options, scattering, roulette, sink);
  }
}

/// A sink that keeps everything (tests).
struct CollectingSink final : PhotonSink {
  std::vector<Photon> surface;
  std::vector<std::vector<Photon>> planes;
  explicit CollectingSink(std::size_t plane_count = 0) : planes(plane_count) {}
  void record(int plane, const Photon& photon) override {
    if (plane < 0) surface.push_back(photon);
    else planes[static_cast<std::size_t>(plane)].push_back(photon);
  }
};

}  // namespace dayphoton::engine::test
