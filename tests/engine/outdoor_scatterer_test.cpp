// Outdoor scatterers (port_emission.h, photon_tracer.h): an exterior system's surfaces as
// emission sites, so that what they reflect or transmit toward a window is traced while the
// window stays the photon port.
//   - An exterior mirror shelf under a glazed window sends the same flux to the ceiling as
//     the same shelf inside a port enclosure (the exact, expensive reference: the box's
//     openings are the ports and the window is plain glazing), under two suns; the walls
//     and floor are black so that the two set-ups model the same light paths.
//   - Without the scatterers (the window alone as port) the shelf only shades: the ceiling
//     gets nothing from it.
//   - Faces of closed solids are lit on their outside only; thin parts on both sides.
//   - Shadow rays of the direct component pass a scatterer's straight transmission (a
//     glazed canopy) after the port, and nothing else.
//   - The low-yield cap: a roof around a small roof opening, drawn as an outdoor scatterer,
//     takes nearly every emission attempt, and the cap scaled by the useful share starves
//     the source; with TracingOptions::raw_attempt_cap the cap is M x target raw attempts.
#include <gtest/gtest.h>

#include <cmath>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/scatterer_sides.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/solar_position.h"
#include "system_scenes.h"

namespace dayphoton::engine {
namespace {

std::vector<Material> models_of(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

double mean3(const Vec3& v) { return (v.x + v.y + v.z) / 3.0; }

Vec3 toward_sun(double altitude_deg, double azimuth_deg) {
  const double a = altitude_deg * Pi / 180, z = azimuth_deg * Pi / 180;
  return {std::cos(a) * std::sin(z), -std::cos(a) * std::cos(z), std::sin(a)};
}

void mark_scatterers(SceneDescription& d, const std::string& prefix) {
  for (Surface& s : d.surfaces)
    if (s.name.compare(0, prefix.size(), prefix) == 0) s.outdoor_scatterer = true;
}

enum class ShelfPorts { Scatterers, Enclosure, WindowOnly };

// 4 x 6 x 3 m room, black walls and floor, white ceiling; glazed window (Tn 0.7) in the
// south wall, x 0.5..3.5, z 1.0..2.8; outside, a slab shelf (mirror top, Lambertian 0.5
// elsewhere) 0.5 m deep, 3 cm thick, 1 mm from the wall, just below the sill.
SceneDescription shelf_scene(ShelfPorts ports) {
  SceneDescription d;
  const int black = test::add_spec(d, test::grey("black", MaterialType::Lambertian, 0.0));
  const int ceiling = test::add_spec(d, test::grey("ceiling", MaterialType::Lambertian, 0.8));
  const int glazing = test::add_spec(d, test::glass_of("glazing", 0.7));
  const int mirror = test::add_spec(d, test::grey("mirror", MaterialType::Mirror, 0.85));
  const int under = test::add_spec(d, test::grey("under", MaterialType::Lambertian, 0.5));
  test::add_room(d, {4, 6, 3}, black, ceiling, black,
                 test::SouthWindow{0.5, 3.5, 1.0, 2.8, glazing, ports != ShelfPorts::Enclosure});
  test::add_box(d, "shelf_out", {0.5, -0.501, 0.97}, {3.5, -0.001, 1.0}, mirror, under);
  if (ports == ShelfPorts::Scatterers) mark_scatterers(d, "shelf_out");
  if (ports == ShelfPorts::Enclosure) {
    const int open = test::add_spec(d, test::material_of("open", MaterialType::Opening));
    test::add_enclosure(d, open, 0.49, 3.51, 0.96, 2.81, 0.511);
  }
  return d;
}

/// Caustic flux stored on the surfaces `where` accepts, per unit sun radiance, and the
/// photon count (20000 caustic photons targeted).
template <typename Where>
std::pair<double, std::size_t> caustic_flux(const SceneDescription& d, const SourceSet& sun, std::uint64_t seed,
                                            Where where) {
  const Scene scene = Scene::build(d);
  TracingOptions o;
  o.photons_per_source = 500;
  o.caustic_photons_per_source = 20000;
  o.seed = seed;
  const TracedPhotons traced = trace_photons(scene, models_of(d), sun, {}, o);
  double flux = 0;
  std::size_t n = 0;
  for (const Photon& p : traced.surface)
    if (p.path_class == PathClass::Caustic && where(p.position_m())) {
      flux += mean3(p.flux_rgb());
      ++n;
    }
  return {flux, n};
}

/// On the ceiling: in these scenes its only light, the sun the mirror reflects through the
/// window.
std::pair<double, std::size_t> ceiling_flux(const SceneDescription& d, const SourceSet& sun, std::uint64_t seed) {
  return caustic_flux(d, sun, seed, [](const Vec3& at) { return at.z > 2.999 && at.y > 0; });
}

TEST(OutdoorScatterers, ExteriorShelfSendsTheEnclosuresFluxToTheCeiling) {
  for (const auto& [alt, az] : {std::pair<double, double>{35, 0}, {55, 30}}) {
    SourceSet sun;
    sun.add_sun_disc(toward_sun(alt, az), sky::SunHalfAngle_rad);
    const auto [with_scatterers, n_s] = ceiling_flux(shelf_scene(ShelfPorts::Scatterers), sun, 5);
    const auto [enclosed, n_e] = ceiling_flux(shelf_scene(ShelfPorts::Enclosure), sun, 6);
    const auto [window_only, n_w] = ceiling_flux(shelf_scene(ShelfPorts::WindowOnly), sun, 7);
    const std::string what = "sun " + std::to_string(int(alt)) + "/" + std::to_string(int(az));
    // The ceiling sees the sky and sun only by the shelf: with the window alone it gets
    // nothing; the mirror's reflection reaches it through the window.
    EXPECT_EQ(window_only, 0.0) << what;
    ASSERT_GT(n_s, 2000u) << what;
    ASSERT_GT(n_e, 2000u) << what;
    // Equal-flux photons within a class (grey materials): each sum's relative standard
    // error is at most 1/sqrt(count); 4 sigma of the difference.
    const double sigma = std::sqrt(with_scatterers * with_scatterers / double(n_s) + enclosed * enclosed / double(n_e));
    EXPECT_NEAR(with_scatterers, enclosed, 4 * sigma)
        << what << ": ceiling flux " << with_scatterers << " (" << n_s << " photons) vs enclosure " << enclosed << " ("
        << n_e << ")";
    RecordProperty(what + " scatterers/enclosure", std::to_string(with_scatterers / enclosed));
  }
}

// A closed dielectric slab (n 1.5, 4 cm, tilted 20 degrees) in front of an unglazed window
// of the same room (grey floor): the light reaching the room passes the slab (refracted:
// caustic) or, above it, nothing. Scatterers and enclosure deliver the same caustic flux.
SceneDescription dielectric_scene(ShelfPorts ports) {
  SceneDescription d;
  const int black = test::add_spec(d, test::grey("black", MaterialType::Lambertian, 0.0));
  const int grey = test::add_spec(d, test::grey("grey", MaterialType::Lambertian, 0.3));
  const int open = test::add_spec(d, test::material_of("open", MaterialType::Opening));
  const int prism = test::add_spec(d, test::dielectric_of("prism", 1.5));
  test::add_room(d, {4, 6, 3}, grey, black, black,
                 test::SouthWindow{0.5, 3.5, 1.0, 2.8, open, ports != ShelfPorts::Enclosure});
  // The slab: x 0.6..3.4, its cross-section a 4 cm x 1.2 m rectangle whose top leans 20
  // degrees toward the wall, foot 0.3 m out at z 1.1.
  const double t = 20 * Pi / 180, w = 0.04, h = 1.2;
  const Vec3 up{0, std::sin(t), std::cos(t)}, across{0, -std::cos(t), std::sin(t)};
  const Vec3 foot{0, -0.3, 1.1};
  const Vec3 p0 = foot, p1 = foot + up * h, p2 = foot + up * h + across * w, p3 = foot + across * w;
  auto at = [](const Vec3& p, double x) { return Vec3{x, p.y, p.z}; };
  const std::vector<std::vector<Vec3>> faces = {
      {at(p0, 0.6), at(p1, 0.6), at(p1, 3.4), at(p0, 3.4)}, {at(p1, 0.6), at(p2, 0.6), at(p2, 3.4), at(p1, 3.4)},
      {at(p2, 0.6), at(p3, 0.6), at(p3, 3.4), at(p2, 3.4)}, {at(p3, 0.6), at(p0, 0.6), at(p0, 3.4), at(p3, 3.4)},
      {at(p0, 0.6), at(p3, 0.6), at(p2, 0.6), at(p1, 0.6)}, {at(p0, 3.4), at(p1, 3.4), at(p2, 3.4), at(p3, 3.4)}};
  const Vec3 centre = (at(p0, 2.0) + at(p2, 2.0)) * 0.5;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    Vec3 c{0, 0, 0};
    for (const Vec3& v : faces[i]) c += v * 0.25;
    test::add_facing(d, "slab." + std::to_string(i), prism, faces[i], c - centre);
  }
  if (ports == ShelfPorts::Scatterers) mark_scatterers(d, "slab");
  if (ports == ShelfPorts::Enclosure) test::add_enclosure(d, open, 0.49, 3.51, 0.99, 2.81, 0.6);
  return d;
}

/// Anywhere in the room.
std::pair<double, std::size_t> room_caustic_flux(const SceneDescription& d, const SourceSet& sun, std::uint64_t seed) {
  return caustic_flux(d, sun, seed, [](const Vec3& at) { return at.y > 0.001; });
}

TEST(OutdoorScatterers, ExteriorDielectricPanelSendsTheEnclosuresFlux) {
  for (const auto& [alt, az] : {std::pair<double, double>{30, 0}, {50, -35}}) {
    SourceSet sun;
    sun.add_sun_disc(toward_sun(alt, az), sky::SunHalfAngle_rad);
    const auto [with_scatterers, n_s] = room_caustic_flux(dielectric_scene(ShelfPorts::Scatterers), sun, 11);
    const auto [enclosed, n_e] = room_caustic_flux(dielectric_scene(ShelfPorts::Enclosure), sun, 12);
    const std::string what = "sun " + std::to_string(int(alt)) + "/" + std::to_string(int(az));
    ASSERT_GT(n_s, 2000u) << what;
    ASSERT_GT(n_e, 2000u) << what;
    const double sigma = std::sqrt(with_scatterers * with_scatterers / double(n_s) + enclosed * enclosed / double(n_e));
    EXPECT_NEAR(with_scatterers, enclosed, 4 * sigma)
        << what << ": caustic flux " << with_scatterers << " (" << n_s << " photons) vs enclosure " << enclosed << " ("
        << n_e << ")";
  }
}

TEST(OutdoorScatterers, ClosedSolidsAreLitOutsideAndThinPartsOnBothSides) {
  SceneDescription d;
  const int m = test::add_spec(d, test::grey("m", MaterialType::Lambertian, 0.5));
  test::add_box(d, "box", {0, 0, 0}, {1, 2, 3}, m, m);
  test::add_facing(d, "plate", m, test::rect_z(5, 6, 5, 6, 1), {0, 0, 1});
  std::vector<int> box, plate = {6}, open_box;
  for (int i = 0; i < 6; ++i) box.push_back(i);
  for (int i = 0; i < 5; ++i) open_box.push_back(i);
  for (LitSides s : scatterer_lit_sides(d, box)) EXPECT_EQ(s, LitSides::Front);
  for (LitSides s : scatterer_lit_sides(d, open_box)) EXPECT_EQ(s, LitSides::Both);
  EXPECT_EQ(scatterer_lit_sides(d, plate)[0], LitSides::Both);
  // Box and plate together: each keeps its own answer.
  std::vector<int> both = box;
  both.push_back(6);
  const std::vector<LitSides> sides = scatterer_lit_sides(d, both);
  EXPECT_EQ(sides[0], LitSides::Front);
  EXPECT_EQ(sides[6], LitSides::Both);
  // Turned inside out (normals inward): lit on the back.
  for (Surface& s : d.surfaces) std::reverse(s.vertices.begin() + 1, s.vertices.end());
  for (LitSides s : scatterer_lit_sides(d, box)) EXPECT_EQ(s, LitSides::Back);
}

TEST(OutdoorScatterers, EmitterBoundCountsEachLitSide) {
  // A thin horizontal plate of 2 m^2 and a unit window facing south (normal +y into the
  // room): a sun 60 degrees high in the north lights the plate's top only (the flux it
  // intercepts is A Omega sin 60); the same sun mirrored below the horizon lights its
  // underside. Neither reaches the window. Tolerance: cos varies by 1e-5 over the disc.
  SceneDescription d;
  const int m = test::add_spec(d, test::grey("m", MaterialType::Lambertian, 0.5));
  const int glass = test::add_spec(d, test::glass_of("glazing", 0.7));
  test::add_facing(d, "window", glass, test::rect_y(0, 1, 0, 1, 0), {0, 1, 0}, true);
  test::add_facing(d, "plate", m, test::rect_z(0, 1, -3, -1, 0.5), {0, 0, 1});
  mark_scatterers(d, "plate");
  const Scene scene = Scene::build(d);
  const double c = std::cos(60 * Pi / 180), s = std::sin(60 * Pi / 180);
  SourceSet sources;
  sources.add_sun_disc({0, c, s}, sky::SunHalfAngle_rad);
  sources.add_sun_disc({0, c, -s}, sky::SunHalfAngle_rad);
  const PortEmitter emitter(scene, sources);
  EXPECT_EQ(emitter.site_count(), 3u);
  const double expected = 2.0 * sources[0].solid_angle_sr * s;
  EXPECT_NEAR(emitter.port_flux(0, 64), expected, 1e-4 * expected);
  EXPECT_NEAR(emitter.port_flux(1, 64), expected, 1e-4 * expected);
  EXPECT_EQ(emitter.port_bound_flux(0), 0.0);
  EXPECT_EQ(emitter.port_bound_flux(1), 0.0);
  EXPECT_GT(emitter.bound_flux(0), expected);  // a true bound
}

TEST(OutdoorScatterers, ShadowRaysPassAScattererCanopyAfterThePort) {
  // A sensor behind a glazed south window (Tn 0.7) looks out and up through a glazed
  // canopy (Tn 0.8) 1 m outside: as a scatterer the canopy transmits (T = 0.7 x 0.8 at
  // normal incidence), as plain outdoor geometry it blocks.
  for (bool scatterer : {true, false}) {
    SceneDescription d;
    const int window = test::add_spec(d, test::glass_of("glazing", 0.7));
    const int canopy = test::add_spec(d, test::glass_of("canopy", 0.8));
    test::add_facing(d, "window", window, test::rect_y(-1, 1, -1, 1, 0), {0, 1, 0}, true);
    test::add_facing(d, "canopy", canopy, test::rect_y(-2, 2, -2, 2, -1), {0, 1, 0});
    if (scatterer) mark_scatterers(d, "canopy");
    const Scene scene = Scene::build(d);
    const std::vector<Material> materials = models_of(d);
    const Vec3 t = sky_transmittance(scene, materials, {0, 0.5, 0}, {0, -1, 0});
    EXPECT_NEAR(mean3(t), scatterer ? 0.7 * 0.8 : 0.0, 1e-9) << (scatterer ? "scatterer" : "plain");
  }
}

// 4 x 4 x 3 m room (Lambertian 0.5) whose only opening is a 0.5 x 0.5 m hole in the ceiling,
// closed by an `opening` port; around it on the roof a 0.3 Lambertian slab 4 x 4 m, drawn as an
// outdoor scatterer: the port's share of the zenith bin's emission bound is 0.8 %.
SceneDescription roof_opening_scene() {
  SceneDescription d;
  const int grey = test::add_spec(d, test::grey("grey", MaterialType::Lambertian, 0.5));
  const int roof = test::add_spec(d, test::grey("roof", MaterialType::Lambertian, 0.3));
  const int open = test::add_spec(d, test::material_of("open", MaterialType::Opening));
  test::add_room(d, {4, 4, 3}, grey, grey, grey, std::nullopt, std::array<double, 4>{1.75, 2.25, 1.75, 2.25});
  test::add_facing(d, "port", open, test::rect_z(1.75, 2.25, 1.75, 2.25, 3), {0, 0, -1}, true);
  test::add_box(d, "roof.w", {0, 0, 3.01}, {1.75, 4, 3.03}, roof, roof);
  test::add_box(d, "roof.e", {2.25, 0, 3.01}, {4, 4, 3.03}, roof, roof);
  test::add_box(d, "roof.s", {1.75, 0, 3.01}, {2.25, 1.75, 3.03}, roof, roof);
  test::add_box(d, "roof.n", {1.75, 2.25, 3.01}, {2.25, 4, 3.03}, roof, roof);
  mark_scatterers(d, "roof.");
  return d;
}

TEST(OutdoorScatterers, RawAttemptCapGivesAStarvedSourceItsTarget) {
  const SceneDescription d = roof_opening_scene();
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  const std::size_t zenith = sources.size() - 1;
  const double share = emitter.port_bound_flux(static_cast<std::uint32_t>(zenith)) /
                       emitter.bound_flux(static_cast<std::uint32_t>(zenith));
  ASSERT_GT(share, 0.005);
  ASSERT_LT(share, 0.05) << "the roof does not dominate the emission bound";
  TracingOptions scaled;
  scaled.photons_per_source = 400;
  scaled.seed = 3;
  TracingOptions raw = scaled;
  raw.raw_attempt_cap = std::vector<char>(sources.size(), 0);
  raw.raw_attempt_cap[zenith] = 1;
  const SourceTally a = trace_source_photons(scene, materials, emitter, {}, scaled, zenith).tallies[0];
  const SourceTally b = trace_source_photons(scene, materials, emitter, {}, raw, zenith).tallies[0];
  const std::uint64_t M = scaled.max_mainpass_attempts_per_target, T = scaled.photons_per_source;
  // The scaled cap: at most M x T x (share + what the roof sends in, an upper bound from the
  // pre-pass) raw attempts, so the port gets ~M T share^2 of them: far below the target
  // (seed 3: 998 main-pass attempts, 32 of 400 photons).
  EXPECT_TRUE(a.capped);
  EXPECT_LT(a.mainpass_attempts, M * T / 10);
  EXPECT_LT(a.stored_global, T / 2);
  // The raw cap: the same pre-pass, then at most M x T main-pass attempts, which the port's
  // yield (about 2 stored photons per port attempt, ~share x 2 per raw attempt) turns into
  // the target within its noise (seed 3: 32,085 attempts, 494 photons).
  EXPECT_EQ(b.prepass_attempts, a.prepass_attempts);
  EXPECT_LE(b.mainpass_attempts, M * T);
  EXPECT_GT(b.mainpass_attempts, a.mainpass_attempts);
  EXPECT_GE(double(b.stored_global), double(T) * (1 - 4 / std::sqrt(double(T))));
  // Both are unbiased: every attempt carries the bound flux over all attempts.
  EXPECT_DOUBLE_EQ(b.flux_per_attempt * double(b.prepass_attempts + b.mainpass_attempts), b.bound_flux);
}

}  // namespace
}  // namespace dayphoton::engine
