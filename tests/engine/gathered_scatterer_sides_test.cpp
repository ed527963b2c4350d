// Direct photons on outdoor scatterers stored only where a final gather can read them
// (gathered_scatterer_sides.h, TracingOptions::scatterer_direct_sides):
//   - an overhang (a closed box of scatterers above a window) keeps its underside and the
//     face toward the wall; its top, front and ends, which neither the window nor a sensor
//     faces, are read by no gather ray;
//   - a sensor outdoors above it, or a mirror canopy that can turn a gather ray onto its top,
//     make the top readable; a material that is not purely diffuse keeps both sides of its
//     own faces (a gather ray goes on from it);
//   - tracing drops exactly the Direct photons of the unread sides, every other photon is the
//     same bit for bit, and a non-diffuse overhang stores exactly as without the rule;
//   - the gathered coefficients at sensors in the room agree with those without the rule
//     within their stated standard errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/gathered_scatterer_sides.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/sky/patch_basis.h"
#include "system_scenes.h"

namespace dayphoton::engine {
namespace {

std::vector<Material> models_of(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

enum class Overhang { Diffuse, Glossy, DiffuseUnderMirror, Translucent };

// 4 x 6 x 3 m room (floor 0.3, ceiling 0.8, walls 0.5), glazed window (Tn 0.7) in the south
// wall x 0.5..3.5, z 1.0..2.5; outside, a Lambertian 0.5 overhang box x 0.3..3.7,
// y -1.0..-0.001, z 2.7..2.8 (its six faces outdoor scatterers), optionally glossy, or
// under a mirror canopy (a scatterer, y -0.9..-0.1, z 3.5: behind the front face's plane).
SceneDescription overhang_scene(Overhang kind) {
  SceneDescription d;
  const int floor = test::add_spec(d, test::grey("floor", MaterialType::Lambertian, 0.3));
  const int ceiling = test::add_spec(d, test::grey("ceiling", MaterialType::Lambertian, 0.8));
  const int walls = test::add_spec(d, test::grey("walls", MaterialType::Lambertian, 0.5));
  const int glazing = test::add_spec(d, test::glass_of("glazing", 0.7));
  MaterialSpec shade = test::grey("shade", MaterialType::Lambertian, 0.5);
  if (kind == Overhang::Glossy) shade.specularity = 0.05;
  if (kind == Overhang::Translucent) {
    shade.type = MaterialType::Translucent;
    shade.transmissivity = 0.5;  // diffuse transmission only (transmitted_specular 0)
  }
  const int overhang = test::add_spec(d, shade);
  test::add_room(d, {4, 6, 3}, floor, ceiling, walls, test::SouthWindow{0.5, 3.5, 1.0, 2.5, glazing});
  test::add_box(d, "overhang", {0.3, -1.0, 2.7}, {3.7, -0.001, 2.8}, overhang, overhang);
  if (kind == Overhang::DiffuseUnderMirror) {
    const int mirror = test::add_spec(d, test::grey("mirror", MaterialType::Mirror, 0.9));
    test::add_facing(d, "canopy", mirror, test::rect_z(0.3, 3.7, -0.9, -0.1, 3.5), {0, 0, -1});
  }
  for (Surface& s : d.surfaces)
    if (s.name.rfind("overhang", 0) == 0 || s.name == "canopy") s.outdoor_scatterer = true;
  return d;
}

// Gathered sensors in the room: three on the work plane, two facing the window (their
// gather rays reach the overhang's underside through it).
std::vector<SensorPoint> room_sensors() {
  return {{{1.0, 1.0, 0.8}, {0, 0, 1}},
          {{2.0, 3.0, 0.8}, {0, 0, 1}},
          {{3.0, 5.0, 0.8}, {0, 0, 1}},
          {{2.0, 0.5, 1.5}, {0, -1, 0}},
          {{1.5, 2.0, 1.2}, {0, -1, 0}}};
}

std::vector<Vec3> positions(const std::vector<SensorPoint>& sensors) {
  std::vector<Vec3> p;
  for (const SensorPoint& s : sensors) p.push_back(s.position);
  return p;
}

// The sides of the scatterer whose surface is named `name`.
std::uint8_t sides_of(const Scene& scene, const std::vector<std::uint8_t>& sides, const std::string& name) {
  const PortSet& scatterers = scene.outdoor_scatterers();
  for (std::size_t i = 0; i < scatterers.size(); ++i)
    if (scene.description().surfaces[static_cast<std::size_t>(scatterers[i].surface)].name == name) return sides[i];
  ADD_FAILURE() << "no scatterer " << name;
  return 0;
}

// A Direct photon on a side of the overhang that no port or sensor faces: its top, front or
// ends, arriving from outside.
bool on_unread_side(const Photon& p) {
  const Vec3 x = p.position_m(), n = p.normal_vector();
  const double tol = 1e-4;
  return (std::fabs(x.z - 2.8) < tol && n.z > 0.5) || (std::fabs(x.y + 1.0) < tol && n.y < -0.5) ||
         (std::fabs(x.x - 0.3) < tol && n.x < -0.5) || (std::fabs(x.x - 3.7) < tol && n.x > 0.5);
}

bool on_underside(const Photon& p) {
  return std::fabs(p.position_m().z - 2.7) < 1e-4 && p.normal_vector().z < -0.5;
}

bool same_bytes(const Photon& a, const Photon& b) { return std::memcmp(&a, &b, sizeof(Photon)) == 0; }

TEST(GatheredScattererSides, AnOverhangKeepsOnlyTheSidesAWindowOrASensorFaces) {
  const SceneDescription d = overhang_scene(Overhang::Diffuse);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  ASSERT_EQ(scene.outdoor_scatterers().size(), 6u);
  const std::vector<std::uint8_t> sides = gathered_scatterer_sides(scene, materials, positions(room_sensors()));
  // The scatterers' normals point out of the box (add_box): the outer sides are the normal sides.
  EXPECT_EQ(sides_of(scene, sides, "overhang.top"), ScattererOppositeSide);
  EXPECT_EQ(sides_of(scene, sides, "overhang.bottom"), ScattererNormalSide);
  EXPECT_EQ(sides_of(scene, sides, "overhang.ymin"), ScattererOppositeSide);
  EXPECT_TRUE(sides_of(scene, sides, "overhang.ymax") & ScattererNormalSide);
  EXPECT_EQ(sides_of(scene, sides, "overhang.xmin"), ScattererOppositeSide);
  EXPECT_EQ(sides_of(scene, sides, "overhang.xmax"), ScattererOppositeSide);

  // A sensor outdoors above the overhang reads its top.
  std::vector<Vec3> outdoors = positions(room_sensors());
  outdoors.push_back({2.0, -0.5, 3.5});
  EXPECT_EQ(sides_of(scene, gathered_scatterer_sides(scene, materials, outdoors), "overhang.top"), ScattererBothSides);

  // A mirror canopy above it can turn a gather ray that left the window onto its top.
  const SceneDescription m = overhang_scene(Overhang::DiffuseUnderMirror);
  const Scene mirrored = Scene::build(m);
  const std::vector<std::uint8_t> under_mirror =
      gathered_scatterer_sides(mirrored, models_of(m), positions(room_sensors()));
  EXPECT_TRUE(sides_of(mirrored, under_mirror, "overhang.top") & ScattererNormalSide);
  EXPECT_EQ(sides_of(mirrored, under_mirror, "overhang.ymin"), ScattererOppositeSide);

  // A translucent (diffusely transmitting) overhang: a lookup on its underside also reads
  // the photons on the other side of the bottom face; its top, which no ray hits, still loses
  // them.
  const SceneDescription t = overhang_scene(Overhang::Translucent);
  const Scene translucent = Scene::build(t);
  const std::vector<Material> translucent_models = models_of(t);
  ASSERT_FALSE(continues_gather(translucent_models.back()));
  const std::vector<std::uint8_t> through = gathered_scatterer_sides(translucent, translucent_models, positions(room_sensors()));
  EXPECT_EQ(sides_of(translucent, through, "overhang.bottom"), ScattererBothSides);
  EXPECT_EQ(sides_of(translucent, through, "overhang.top"), ScattererBothSides);  // its inner side is read
  // A glossy overhang sends gather rays on from every face: every side is kept.
  const SceneDescription g = overhang_scene(Overhang::Glossy);
  const Scene glossy = Scene::build(g);
  for (const std::uint8_t s : gathered_scatterer_sides(glossy, models_of(g), positions(room_sensors())))
    EXPECT_EQ(s, ScattererBothSides);
}

TEST(GatheredScattererSides, WhichMaterialsSendAGatherRayOn) {
  EXPECT_FALSE(continues_gather(Material::from_spec(test::grey("white", MaterialType::Lambertian, 0.8))));
  EXPECT_FALSE(continues_gather(Material::from_spec(test::grey("black", MaterialType::Lambertian, 0.0))));
  MaterialSpec plastic = test::grey("plastic", MaterialType::Lambertian, 0.5);
  plastic.specularity = 0.05;
  EXPECT_TRUE(continues_gather(Material::from_spec(plastic)));
  plastic.roughness = 0.1;
  EXPECT_TRUE(continues_gather(Material::from_spec(plastic)));
  EXPECT_TRUE(continues_gather(Material::from_spec(test::grey("mirror", MaterialType::Mirror, 0.9))));
  EXPECT_TRUE(continues_gather(Material::from_spec(test::glass_of("glass", 0.7))));
  EXPECT_TRUE(continues_gather(Material::from_spec(test::material_of("open", MaterialType::Opening))));
}

// Attempts [0, 20000) of a few sky sources, with and without the rule: the rule's photons are
// those without it less the Direct photons of the unread sides, in order, bit for bit.
// Returns the dropped and kept counts.
std::pair<std::size_t, std::size_t> compare_attempts(Overhang kind, std::size_t& underside) {
  const SceneDescription d = overhang_scene(kind);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  TracingOptions all;
  all.store_direct_on_surfaces = true;
  all.seed = 11;
  TracingOptions rule = all;
  rule.scatterer_direct_sides = gathered_scatterer_sides(scene, materials, positions(room_sensors()));
  std::size_t dropped = 0, kept = 0;
  underside = 0;
  for (const std::size_t source : {std::size_t(0), std::size_t(20), std::size_t(60), std::size_t(110), std::size_t(144)}) {
    const TracedPhotons a = trace_source_attempts(scene, materials, emitter, {}, all, source, 0, 20000);
    const TracedPhotons b = trace_source_attempts(scene, materials, emitter, {}, rule, source, 0, 20000);
    std::size_t j = 0;
    for (const Photon& p : a.surface) {
      if (j < b.surface.size() && same_bytes(p, b.surface[j])) {
        ++j;
        ++kept;
        if (p.path_class == PathClass::Direct && on_underside(p)) ++underside;
        continue;
      }
      // Not kept: only a Direct photon on a side nobody reads may be missing.
      EXPECT_EQ(p.path_class, PathClass::Direct) << "source " << source;
      EXPECT_TRUE(on_unread_side(p)) << "source " << source << " at " << p.position_m().x << ' '
                                     << p.position_m().y << ' ' << p.position_m().z;
      ++dropped;
    }
    EXPECT_EQ(j, b.surface.size()) << "source " << source << ": the rule's photons are not a subsequence";
    EXPECT_EQ(a.tallies[0].stored_direct, b.tallies[0].stored_direct + (a.surface.size() - b.surface.size()));
  }
  return {dropped, kept};
}

TEST(GatheredScattererSides, TracingDropsOnlyTheDirectPhotonsOfUnreadSides) {
  std::size_t underside = 0;
  const auto [dropped, kept] = compare_attempts(Overhang::Diffuse, underside);
  RecordProperty("dropped", std::to_string(dropped));
  RecordProperty("kept", std::to_string(kept));
  EXPECT_GT(dropped, 1000u);  // the overhang's top takes most of the high sky bins' light
  EXPECT_GT(underside, 100u);  // the ground bin lights its underside, which the window sees
}

TEST(GatheredScattererSides, ANonDiffuseOverhangStoresAsBefore) {
  std::size_t underside = 0;
  const auto [dropped, kept] = compare_attempts(Overhang::Glossy, underside);
  EXPECT_EQ(dropped, 0u);
  EXPECT_GT(kept, 1000u);
}

TEST(GatheredScattererSides, GatheredCoefficientsAgreeWithinTheirErrors) {
  const SceneDescription d = overhang_scene(Overhang::Diffuse);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const std::vector<SensorPoint> sensors = room_sensors();
  TracingOptions all;
  all.photons_per_source = 2000;
  all.store_direct_on_surfaces = true;
  all.seed = 5;
  TracingOptions rule = all;
  rule.scatterer_direct_sides = gathered_scatterer_sides(scene, materials, positions(sensors));
  CoefficientOptions co;
  co.gather.rays_per_sensor = 256;
  co.gather.seed = 9;
  struct Run {
    std::vector<double> total, variance;
    std::size_t photons = 0;
  };
  auto run = [&](const TracingOptions& o) {
    const TracedPhotons traced = trace_photons(scene, materials, sources, {}, o);
    Run r;
    r.photons = traced.surface.size();
    const GridPhotons gather = GridPhotons::for_gather(traced.surface, sources.size());
    DaylightCoefficients g;
    g.sensors = sensors.size();
    g.sources = sources.size();
    photon_coefficients(scene, materials, sources, gather, sensors, co, g);
    EXPECT_EQ(g.photon_variance.size(), sensors.size() * sources.size());
    r.total.assign(sensors.size(), 0.0);
    r.variance.assign(sensors.size(), 0.0);
    // Unit radiance in every bin: the sum over sources, and its variance (independent sources).
    for (std::size_t s = 0; s < sensors.size(); ++s)
      for (std::size_t p = 0; p < sources.size(); ++p) {
        const std::size_t i = s * sources.size() + p;
        r.total[s] += luminance_of(g.caustic[i] + g.global[i]);
        r.variance[s] += g.photon_variance[i];
      }
    return r;
  };
  const Run before = run(all), after = run(rule);
  EXPECT_LT(after.photons, before.photons);
  RecordProperty("photons without / with the rule", std::to_string(before.photons) + " / " + std::to_string(after.photons));
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    ASSERT_GT(before.total[s], 0.0);
    // 4 combined standard errors (both runs' stated variances): at 5 sensors a false failure
    // of independent runs has probability below 4e-4; the runs share their seeds, so it is
    // lower still. Dropping a side the gather reads (the underside) would fail it.
    const double sigma = std::sqrt(before.variance[s] + after.variance[s]);
    EXPECT_NEAR(after.total[s], before.total[s], 4 * sigma)
        << "sensor " << s << ": " << after.total[s] << " vs " << before.total[s] << " +- " << sigma;
  }
}

}  // namespace
}  // namespace dayphoton::engine
