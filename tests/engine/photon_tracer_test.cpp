// Forward pass: furnace closed forms (seeds/000 chapter 6, digest T-1/T-2/T-12), port flux
// normalisation (T-14), port emission against brute-force emission from a surrounding sky
// (T-15), photon-count control (T-11) and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <numeric>
#include <optional>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/density_estimate.h"
#include "dayphoton/engine/photon_map.h"
#include "dayphoton/engine/photon_rounds.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "light_tracing_reference.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

std::vector<Material> models_of(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

Vec3 uniform_sphere(double u1, double u2) {
  const double z = 1 - 2 * u1, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * Pi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// ---- furnace -------------------------------------------------------------------------------

struct FurnaceResult {
  Vec3 total_over_el;       ///< sum of stored flux / (Phi / A): the sphere-average E_ind / E_l
  Vec3 batch_sigma;         ///< standard error of total_over_el from 16 batch means
  Vec3 knn_over_el;         ///< mean of kNN estimates at random points / E_l
  std::size_t stored = 0;
};

// Unit icosphere (5120 triangles) with Lambertian reflectance rho, isotropic point source
// of total flux Phi = 4 pi at the centre, `emitted` photons. The first hit is direct and not
// stored, so the stored photons estimate the indirect irradiance rho / (1 - rho) E_l
// (seeds/000 eqs. 6.3-6.9) with E_l = Phi / A for the mesh area A.
FurnaceResult run_furnace(const Vec3& rho, std::uint64_t emitted, std::size_t points) {
  SceneDescription d;
  MaterialSpec m;
  m.name = "inside";
  m.type = MaterialType::Lambertian;
  m.reflectance = rho;
  d.materials.push_back(m);
  test::add_inward_sphere(d, 0, 1.0, 4);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  double area = 0;
  std::vector<double> cumulative;
  for (std::size_t t = 0; t < scene.triangle_count(); ++t) {
    const auto& v = scene.triangle(static_cast<std::uint32_t>(t)).vertices;
    area += 0.5 * length(cross(v[1] - v[0], v[2] - v[0]));
    cumulative.push_back(area);
  }
  const double phi_total = 4 * Pi;
  const double e_l = phi_total / area;

  constexpr int Batches = 16;
  std::vector<Vec3> batch(Batches, Vec3{0, 0, 0});
  std::vector<Photon> photons;
  TracingOptions options;
  for (std::uint64_t i = 0; i < emitted; ++i) {
    Rng emission(7, 0, i, RandomStream::Emission);
    PathStart start;
    start.origin = {0, 0, 0};
    start.direction = uniform_sphere(emission.uniform(), emission.uniform());
    start.flux = Vec3{1, 1, 1} * (phi_total / double(emitted));
    Rng scattering(7, 0, i, RandomStream::Scattering), roulette(7, 0, i, RandomStream::Roulette);
    test::CollectingSink sink;
    trace_path(scene, materials, {}, start, options, scattering, roulette, sink);
    for (const Photon& p : sink.surface) {
      EXPECT_EQ(p.path_class, PathClass::Global);
      batch[i % Batches] = batch[i % Batches] + p.flux_rgb();
      photons.push_back(p);
    }
  }
  FurnaceResult r;
  r.stored = photons.size();
  Vec3 sum{0, 0, 0};
  for (const Vec3& b : batch) sum = sum + b;
  r.total_over_el = sum * (1.0 / (area * e_l));
  // Batch b estimates the total as Batches * batch[b]; its spread gives the standard error.
  Vec3 var{0, 0, 0};
  for (const Vec3& b : batch) {
    const Vec3 dev = b * double(Batches) * (1.0 / (area * e_l)) - r.total_over_el;
    var = var + mul(dev, dev);
  }
  var = var * (1.0 / (Batches - 1) / Batches);
  r.batch_sigma = {std::sqrt(var.x), std::sqrt(var.y), std::sqrt(var.z)};

  const PhotonMap map(std::move(photons));
  DensityEstimateOptions eo;
  eo.bandwidth = std::max<std::size_t>(50, r.stored / 20);  // 0.05 N, as in the thesis
  Vec3 knn{0, 0, 0};
  for (std::size_t k = 0; k < points; ++k) {
    Rng rng(11, 1, k, RandomStream::Estimate);
    const double u = rng.uniform() * area;
    const std::size_t t =
        std::lower_bound(cumulative.begin(), cumulative.end(), u) - cumulative.begin();
    const auto& v = scene.triangle(static_cast<std::uint32_t>(std::min(t, cumulative.size() - 1))).vertices;
    double a = rng.uniform(), b = rng.uniform();
    if (a + b > 1) { a = 1 - a; b = 1 - b; }
    const Vec3 at = v[0] + (v[1] - v[0]) * a + (v[2] - v[0]) * b;
    PhotonFilter f;
    knn = knn + estimate_irradiance(map, at, f, eo).irradiance;
  }
  r.knn_over_el = knn * (1.0 / (double(points) * e_l));
  return r;
}

TEST(Furnace, GreySphereIndirectIsRhoOverOneMinusRho) {
  // T-1: rho = 0.9, indirect E / E_l = 9. Tolerance of the digest: 3 / sqrt((1 - rho)
  // N_stored) (the relative sigma of the total stored flux, digest section 5.1) + 0.2 %.
  const double rho = 0.9;
  const FurnaceResult r = run_furnace({rho, rho, rho}, 40000, 1000);
  const double expected = rho / (1 - rho);
  const double tol = 3.0 / std::sqrt((1 - rho) * double(r.stored)) + 0.002;
  EXPECT_NEAR(r.total_over_el.x / expected, 1.0, tol);
  EXPECT_NEAR(r.knn_over_el.x / expected, 1.0, tol) << "stored " << r.stored;
}

TEST(Furnace, ColouredSphereNeedsFluxWeightedRoulette) {
  // T-12: rho = (0.9, 0.5, 0.2), white source: E_c / E_l = 1 / (1 - rho_c), i.e. indirect
  // (9, 1, 0.25). A plain-mean survival probability gives about (2.40, 0.79, 0.24) for the
  // indirect part (digest section 2.1.4), far outside the tolerance. Tolerance per channel:
  // 4 standard errors from 16 batch means + 0.2 % bias budget.
  const Vec3 rho{0.9, 0.5, 0.2};
  const FurnaceResult r = run_furnace(rho, 40000, 400);
  const Vec3 expected{rho.x / (1 - rho.x), rho.y / (1 - rho.y), rho.z / (1 - rho.z)};
  for (int c = 0; c < 3; ++c) {
    const double e = c == 0 ? expected.x : c == 1 ? expected.y : expected.z;
    const double got = c == 0 ? r.total_over_el.x : c == 1 ? r.total_over_el.y : r.total_over_el.z;
    const double sigma = c == 0 ? r.batch_sigma.x : c == 1 ? r.batch_sigma.y : r.batch_sigma.z;
    EXPECT_NEAR(got, e, 4 * sigma + 0.002 * e) << "channel " << c;
    const double knn = c == 0 ? r.knn_over_el.x : c == 1 ? r.knn_over_el.y : r.knn_over_el.z;
    EXPECT_NEAR(knn, e, 4 * sigma + 0.01 * e) << "kNN, channel " << c;
  }
}

// ---- ports -----------------------------------------------------------------------------------

// 4 x 4 x 3 m box; the whole ceiling is an opening port (normal down, into the room).
SceneDescription skylight_room() {
  SceneDescription d;
  const int wall = test::add_material(d, "black", MaterialType::Lambertian, 0.0);
  MaterialSpec open;
  open.name = "open";
  open.type = MaterialType::Opening;
  d.materials.push_back(open);
  test::add_surface(d, "floor", wall, {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
  test::add_surface(d, "skylight", 1, {{0, 0, 3}, {0, 4, 3}, {4, 4, 3}, {4, 0, 3}}, true);
  test::add_surface(d, "w0", wall, {{0, 0, 0}, {0, 4, 0}, {0, 4, 3}, {0, 0, 3}});
  test::add_surface(d, "w1", wall, {{4, 0, 0}, {4, 0, 3}, {4, 4, 3}, {4, 4, 0}});
  test::add_surface(d, "w2", wall, {{0, 0, 0}, {0, 0, 3}, {4, 0, 3}, {4, 0, 0}});
  test::add_surface(d, "w3", wall, {{0, 4, 0}, {4, 4, 0}, {4, 4, 3}, {0, 4, 3}});
  return d;
}

// 3 x 4 x 2.5 m room, window 2 x 1.2 m (sill 0.8) in the south wall y = 0, material `glazing`.
SceneDescription window_room(MaterialType glazing, double wall_rho = 0.5) {
  SceneDescription d;
  const int floor = test::add_material(d, "floor", MaterialType::Lambertian, 0.3);
  const int wall = test::add_material(d, "wall", MaterialType::Lambertian, wall_rho);
  const int ceiling = test::add_material(d, "ceiling", MaterialType::Lambertian, 0.7);
  const int glass = test::add_material(d, "glazing", glazing, 0.0);
  test::add_surface(d, "floor", floor, {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}});
  test::add_surface(d, "ceiling", ceiling, {{0, 0, 2.5}, {0, 4, 2.5}, {3, 4, 2.5}, {3, 0, 2.5}});
  test::add_surface(d, "west", wall, {{0, 0, 0}, {0, 4, 0}, {0, 4, 2.5}, {0, 0, 2.5}});
  test::add_surface(d, "east", wall, {{3, 0, 0}, {3, 0, 2.5}, {3, 4, 2.5}, {3, 4, 0}});
  test::add_surface(d, "north", wall, {{0, 4, 0}, {3, 4, 0}, {3, 4, 2.5}, {0, 4, 2.5}});
  test::add_surface(d, "sill", wall, {{0, 0, 0}, {0, 0, 0.8}, {3, 0, 0.8}, {3, 0, 0}});
  test::add_surface(d, "head", wall, {{0, 0, 2.0}, {0, 0, 2.5}, {3, 0, 2.5}, {3, 0, 2.0}});
  test::add_surface(d, "jamb_w", wall, {{0, 0, 0.8}, {0, 0, 2.0}, {0.5, 0, 2.0}, {0.5, 0, 0.8}});
  test::add_surface(d, "jamb_e", wall, {{2.5, 0, 0.8}, {2.5, 0, 2.0}, {3, 0, 2.0}, {3, 0, 0.8}});
  test::add_surface(d, "window", glass, {{0.5, 0, 0.8}, {0.5, 0, 2.0}, {2.5, 0, 2.0}, {2.5, 0, 0.8}},
                    true);
  return d;
}

ReceiverPlane work_plane(double x_m, double y_m, double z_m) {
  return ReceiverPlane(z_m, true, {{0, 0}, {x_m, 0}, {x_m, y_m}, {0, y_m}});
}

TEST(PortEmission, SkylightUnderUniformSkyReceivesPiLA) {
  // T-14: a horizontal port of area A under a sky of unit radiance: Phi = pi A; the ground
  // bin sends nothing down through it.
  const Scene scene = Scene::build(skylight_room());
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  double sky = 0;
  for (std::size_t p = 1; p < sources.size(); ++p) {
    sky += emitter.port_flux(p);
    EXPECT_GE(emitter.bound_flux(p), emitter.port_flux(p)) << "bin " << p;
  }
  EXPECT_NEAR(sky / (Pi * 16.0), 1.0, 1e-4);  // midpoint quadrature, 256^2 nodes per bin
  EXPECT_EQ(emitter.port_flux(0), 0.0);
}

TEST(PortEmission, VerticalWindowReceivesHalfFromSkyHalfFromGround) {
  // T-14: a vertical port of area A: pi A / 2 from the sky above the horizon, pi A / 2 from
  // the ground bin.
  const Scene scene = Scene::build(window_room(MaterialType::Opening));
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  const double area = 2.0 * 1.2;
  double sky = 0;
  for (std::size_t p = 1; p < sources.size(); ++p) sky += emitter.port_flux(p);
  EXPECT_NEAR(sky / (Pi * area / 2), 1.0, 1e-4);
  EXPECT_NEAR(emitter.port_flux(0) / (Pi * area / 2), 1.0, 1e-4);
}

TEST(PortEmission, BinsBehindThePortCostNoAttempts) {
  // The sky bins of the northern half and those whose edge lies in the plane of the south
  // window send no light through it: their emission bound is exactly zero (exact per-cell
  // bounds, port_emission.h), so the tracer spends no attempts on them; every other bin's
  // bound is at least its flux.
  const Scene scene = Scene::build(window_room(MaterialType::Opening));
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  int dark = 0;
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const double flux = emitter.port_flux(p, 32);
    if (flux == 0) {
      EXPECT_EQ(emitter.bound_flux(p), 0.0) << "bin " << p;
      ++dark;
    } else {
      EXPECT_GE(emitter.bound_flux(p), flux) << "bin " << p;
    }
  }
  EXPECT_GE(dark, 60);  // 145 sky bins: more than the northern half of each row faces away
}

TEST(PortEmission, AcceptedAttemptsCarryThePortFlux) {
  // Rejection emission is exact: accepted / attempts * bound = port flux. Binomial standard
  // error sqrt(f (1 - f) / n) * bound; 4 sigma.
  const Scene scene = Scene::build(window_room(MaterialType::Opening));
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  for (std::size_t p : {0u, 5u, 40u, 100u, 145u}) {
    const std::uint64_t n = 200000;
    std::uint64_t accepted = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      Rng rng(3, p, i, RandomStream::Emission);
      const auto entry = emitter.attempt(p, rng);
      if (!entry) continue;
      ++accepted;
      EXPECT_GT(dot(entry->direction, scene.ports()[0].normal), 0.0);
    }
    const double f = double(accepted) / double(n);
    const double sigma = std::sqrt(f * (1 - f) / double(n)) * emitter.bound_flux(p);
    EXPECT_NEAR(f * emitter.bound_flux(p), emitter.port_flux(p), 4 * sigma + 1e-12) << "bin " << p;
  }
}

double indirect_plane_flux(const std::vector<Photon>& photons) {
  double sum = 0;
  for (const Photon& p : photons)
    if (p.path_class != PathClass::Direct) sum += (p.flux[0] + p.flux[1] + p.flux[2]) / 3.0;
  return sum;
}

/// sqrt(sum f_i^2) / sum f_i over the photons indirect_plane_flux sums.
double relative_error(const std::vector<Photon>& photons) {
  double sum = 0, squares = 0;
  for (const Photon& p : photons)
    if (p.path_class != PathClass::Direct) {
      const double f = (p.flux[0] + p.flux[1] + p.flux[2]) / 3.0;
      sum += f;
      squares += f * f;
    }
  return std::sqrt(squares) / sum;
}

TEST(PortEmission, EqualsBruteForceEmissionFromTheSurroundingSky) {
  // T-15: the indirect flux crossing the work plane under a uniform sky (unit radiance over
  // the whole sphere, ground included) is the same whether photons enter through the port
  // or are shot at the whole building from a disc around it. Each estimate's standard error
  // comes from 8 batch means; tolerance 4 combined sigma.
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());

  constexpr int Batches = 8;
  std::vector<double> port_batches, brute_batches;
  for (int b = 0; b < Batches; ++b) {
    TracingOptions o;
    o.photons_per_source = 300;
    o.seed = 100 + b;
    const TracedPhotons traced = trace_photons(scene, materials, sources, planes, o);
    port_batches.push_back(indirect_plane_flux(traced.planes[0]));
  }
  const std::uint64_t brute_total = 1600000;
  for (int b = 0; b < Batches; ++b) {
    test::CollectingSink sink(1);
    TracingOptions o;
    const std::uint64_t per = brute_total / Batches;
    test::brute_force_emission(scene, materials, planes, uniform_sphere, 4 * Pi,
                               [](const Vec3&) { return Vec3{1, 1, 1}; }, b * per, per, per, 5, o,
                               sink);
    brute_batches.push_back(indirect_plane_flux(sink.planes[0]));
  }
  auto mean_and_se = [](const std::vector<double>& v) {
    const double m = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
    double var = 0;
    for (double x : v) var += (x - m) * (x - m);
    return std::make_pair(m, std::sqrt(var / double(v.size() - 1) / double(v.size())));
  };
  const auto [port, port_se] = mean_and_se(port_batches);
  const auto [brute, brute_se] = mean_and_se(brute_batches);
  EXPECT_NEAR(port, brute, 4 * std::hypot(port_se, brute_se))
      << "port " << port << " +- " << port_se << ", brute force " << brute << " +- " << brute_se;
}

TEST(ReceiverPlanes, APlaneOnTheFloorOrTheCeilingCountsThePhotonsThatLandThere) {
  // A grid on the floor (height 0) or on the ceiling facing down lies on a surface: every
  // photon that crosses a plane 1 mm off that surface, towards it, goes on to land on it, so
  // the plane on the surface must count the same flux. The hit's distance and the crossing's
  // agree only to rounding; the strict t < t_hit lost every one of them (a floor grid's DF read
  // 8-68 % low, a ceiling grid's 25-85 %). Same paths for all four planes, so the only
  // difference is the light that reaches the 1 mm strip along the walls between the planes:
  // below 0.1 %.
  const SceneDescription d = window_room(MaterialType::Opening);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<PlanePoint> outline = {{0, 0}, {3, 0}, {3, 4}, {0, 4}};
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.0, true, outline), ReceiverPlane(0.001, true, outline),
                                             ReceiverPlane(2.5, false, outline),
                                             ReceiverPlane(2.499, false, outline)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  TracingOptions o;
  o.photons_per_source = 300;
  const TracedPhotons traced = trace_photons(scene, materials, sources, planes, o);
  const double floor = indirect_plane_flux(traced.planes[0]);
  const double above_floor = indirect_plane_flux(traced.planes[1]);
  const double ceiling = indirect_plane_flux(traced.planes[2]);
  const double below_ceiling = indirect_plane_flux(traced.planes[3]);
  ASSERT_GT(above_floor, 0);
  ASSERT_GT(below_ceiling, 0);
  EXPECT_NEAR(floor / above_floor, 1.0, 1e-3);
  EXPECT_NEAR(ceiling / below_ceiling, 1.0, 1e-3);
  EXPECT_NEAR(double(traced.planes[0].size()) / double(traced.planes[1].size()), 1.0, 1e-3);
  EXPECT_NEAR(double(traced.planes[2].size()) / double(traced.planes[3].size()), 1.0, 1e-3);
  for (const Photon& p : traced.planes[0]) ASSERT_EQ(p.position[2], 0.0f);
  for (const Photon& p : traced.planes[2]) ASSERT_EQ(p.position[2], 2.5f);
}

// ---- photon-count control and determinism ------------------------------------------------

TEST(PhotonCounts, EverySourceReachesItsTargetAndFluxDoesNotDependOnIt) {
  // T-11: stored >= target (the main pass is sized from the pre-pass yield, so a shortfall
  // larger than a few sigma of the yield would be a bug), and the expected stored flux is
  // the same whatever the target.
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  TracingOptions o;
  o.photons_per_source = 2000;
  const TracedPhotons traced = trace_photons(scene, materials, sources, planes, o);
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const SourceTally& t = traced.tallies[p];
    if (t.entered == 0) continue;  // bins behind the window plane: the port sees none
    // The top-up run is sized from the main pass's yield (>= ~1000 photons), so the count
    // may fall short only by the noise of the photons still missing: 4 / sqrt(target).
    const double slack = 4.0 / std::sqrt(double(o.photons_per_source));
    EXPECT_GE(double(t.stored_global), double(o.photons_per_source) * (1 - slack)) << "bin " << p;
    EXPECT_LE(t.storage_probability_global, 1.0);
  }
  // Four times fewer photons: the same expected flux on the plane. A source's photons carry
  // equal flux, but sources differ (the ground bin's photons, as many as a sky patch's,
  // carry the flux of a hemisphere), so each total of independent photons of flux f_i has
  // the relative standard error sqrt(sum f_i^2) / sum f_i, not 1 / sqrt(count); 4 sigma.
  TracingOptions fewer = o;
  fewer.photons_per_source = 500;
  fewer.seed = 2;
  const TracedPhotons small = trace_photons(scene, materials, sources, planes, fewer);
  const double big_flux = indirect_plane_flux(traced.planes[0]);
  const double small_flux = indirect_plane_flux(small.planes[0]);
  const double sigma = std::hypot(relative_error(traced.planes[0]), relative_error(small.planes[0]));
  EXPECT_NEAR(small_flux / big_flux, 1.0, 4 * sigma);
}

TEST(PhotonCounts, OneAndTwoThreadsGiveBitIdenticalPhotons) {
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  TracingOptions o;
  o.photons_per_source = 300;
  auto run = [&](int threads) {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, threads);
    return trace_photons(scene, materials, sources, planes, o);
  };
  const TracedPhotons a = run(1), b = run(2);
  ASSERT_EQ(a.surface.size(), b.surface.size());
  ASSERT_EQ(a.planes[0].size(), b.planes[0].size());
  EXPECT_EQ(0, std::memcmp(a.surface.data(), b.surface.data(), a.surface.size() * sizeof(Photon)));
  EXPECT_EQ(0, std::memcmp(a.planes[0].data(), b.planes[0].data(),
                           a.planes[0].size() * sizeof(Photon)));
}

// FNV-1a (Fowler, Noll and Vo), 64-bit, over every byte of the records and the counts of the
// tallies, in order. The records' sky ratio codes (all SkyRatioOne without sky ratios, which
// the caller checks) and sky quadrants are hashed as 0: the digests were recorded before the
// records had them, and neither changes a path (the quadrants are checked by
// PhotonPartOnSky.EverySkyPhotonRecordsTheQuadrantItWasEmittedInto).
std::uint64_t photon_digest(const TracedPhotons& t) {
  std::uint64_t hash = 14695981039346656037ull;
  auto eat = [&hash](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  };
  auto eat_photons = [&eat](const std::vector<Photon>& photons) {
    for (Photon p : photons) {
      p.sky_ratio_code = 0;
      p.sky_quadrant = 0;
      eat(&p, sizeof p);
    }
  };
  eat_photons(t.surface);
  for (const std::vector<Photon>& plane : t.planes) eat_photons(plane);
  for (const SourceTally& tally : t.tallies)
    for (const std::uint64_t v : {tally.prepass_attempts, tally.mainpass_attempts, tally.entered, tally.stored_global,
                                  tally.stored_caustic, tally.stored_direct, tally.rays})
      eat(&v, sizeof v);
  return hash;
}

TEST(PhotonCounts, PhotonsArePinned) {
  // Photon i of a source is a pure function of (seed, source, i): changes made for speed
  // (inlined rounding, hashing the seed and source once per source, the pure diffuse
  // reflector's sampling without the component selection) must leave every byte as it was.
  // The digests were recorded with the tracer of main c1bb538 on the project's machine kind
  // (Debian's glibc libm: another libm may round a sine or a power differently in the last
  // bit); a change that alters the photons on purpose must say why and record new ones. Both grey (glass) and coloured
  // (plastic with a specular part, sampled through the component selection) rooms.
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  TracingOptions o;
  o.photons_per_source = 200;
  const SceneDescription grey = window_room(MaterialType::Glass);
  SceneDescription glossy = window_room(MaterialType::Glass);
  for (MaterialSpec& m : glossy.materials)
    if (m.name == "wall") {
      m.reflectance = {0.6, 0.5, 0.3};
      m.specularity = 0.05;
      m.roughness = 0.1;
    }
  const std::pair<const SceneDescription*, std::uint64_t> cases[] = {{&grey, 0x303dbd24dbd05da4ull}, {&glossy, 0x2e00d3b188f390c6ull}};
  for (const auto& [d, expected] : cases) {
    const Scene scene = Scene::build(*d);
    const TracedPhotons t = trace_photons(scene, models_of(*d), sources, planes, o);
    EXPECT_EQ(photon_digest(t), expected) << std::hex << photon_digest(t);
    for (const Photon& p : t.surface) ASSERT_EQ(p.sky_ratio_code, SkyRatioOne);
    for (const Photon& p : t.planes[0]) ASSERT_EQ(p.sky_ratio_code, SkyRatioOne);
  }
}

// ---- cancellation ------------------------------------------------------------------------

// When one iteration of an enclosing parallel loop throws (the run's cache write on a full
// disk, bad_alloc), TBB cancels its task group: the photon pass running in another iteration
// sees its own nested parallel loop return early, with blocks that never ran. The pass must
// then throw, never merge those blocks (it used to read their empty plane lists: a segfault).
// Cancelling the enclosing group from inside the iteration is exactly what TBB does when a
// sibling throws, without depending on timing.
TEST(PhotonCancellation, CancelledEnclosingLoopMakesThePassThrowInsteadOfMergingMissingBlocks) {
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  SourceSet sources;
  sources.add_sun_disc({0, -std::cos(40 * Pi / 180), std::sin(40 * Pi / 180)}, 0.00465);
  const PortEmitter emitter(scene, sources);
  TracingOptions o;
  o.photons_per_source = 5000;
  tbb::task_group_context enclosing;
  std::exception_ptr error;
  bool returned = false;
  tbb::parallel_for(0, 1, [&](int) {
    enclosing.cancel_group_execution();
    try {
      trace_source_photons(scene, materials, emitter, planes, o, 0);
      returned = true;
    } catch (...) {
      error = std::current_exception();
    }
  }, enclosing);
  EXPECT_FALSE(returned) << "a cancelled pass returned photons as if it were complete";
  ASSERT_TRUE(error);
  try {
    std::rethrow_exception(error);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos) << e.what();
  }
}

// The same through the public entry point, as the study uses it: every source's iteration
// traces and then throws (each cache write fails). The first exception reaches the caller,
// whatever the other sources' passes were doing when the loop was cancelled.
TEST(PhotonCancellation, ThrowAfterEachSourceReachesTheCallerUnchanged) {
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  TracingOptions o;
  o.photons_per_source = 20000;  // tens of blocks per source: cancellation finds passes mid-way
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 4);
  try {
    tbb::parallel_for(std::size_t(0), sources.size(), [&](std::size_t p) {
      trace_source_photons(scene, materials, emitter, planes, o, p);
      throw std::runtime_error("cannot write the cache: no space left on device");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "cannot write the cache: no space left on device");
  }
}

// ---- low-yield cap ------------------------------------------------------------------------

// window_room with a black screen 0.5 m outside the window, parallel to it, open only in a
// `hole_m` square in front of the window's centre: the sun disc due south at 30 degrees
// reaches the port only through the hole, so most attempts are shaded and the source stores
// few photons per attempt (a port seen through a sliver).
SceneDescription screened_window_room(double hole_m) {
  SceneDescription d = window_room(MaterialType::Opening);
  const int black = test::add_material(d, "screen", MaterialType::Lambertian, 0.0);
  const double y = -0.5, x0 = 1.5 - hole_m / 2, x1 = 1.5 + hole_m / 2;
  const double z0 = 1.4 - hole_m / 2, z1 = 1.4 + hole_m / 2;
  test::add_surface(d, "screen_w", black, {{-1, y, -1}, {x0, y, -1}, {x0, y, 4}, {-1, y, 4}});
  test::add_surface(d, "screen_e", black, {{x1, y, -1}, {4, y, -1}, {4, y, 4}, {x1, y, 4}});
  test::add_surface(d, "screen_s", black, {{x0, y, -1}, {x1, y, -1}, {x1, y, z0}, {x0, y, z0}});
  test::add_surface(d, "screen_n", black, {{x0, y, z1}, {x1, y, z1}, {x1, y, 4}, {x0, y, 4}});
  return d;
}

SourceSet low_sun() {
  SourceSet s;
  s.add_sun_disc({0, -std::cos(30 * Pi / 180), std::sin(30 * Pi / 180)}, 0.00465);
  return s;
}

double stored_flux(const TracedPhotons& t) {
  return indirect_plane_flux(t.surface) + indirect_plane_flux(t.planes[0]);
}

std::uint64_t attempts_of(const SourceTally& t) { return t.prepass_attempts + t.mainpass_attempts; }

TEST(PhotonCap, BoundsTheAttemptsOfALowYieldSource) {
  // A 3 cm hole in front of a 2 x 1.2 m window: ~0.04 % of the port is lit, so the source
  // stores ~1 photon per 900 attempts (the first scattering event in the room keeps its
  // photon, weighted) and, uncapped, needs ~target / yield attempts.
  const SceneDescription d = screened_window_room(0.03);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = low_sun();
  const PortEmitter emitter(scene, sources);
  TracingOptions capped;
  capped.photons_per_source = 200;
  ASSERT_EQ(capped.max_mainpass_attempts_per_target, 256u);  // the default caps
  TracingOptions uncapped = capped;
  uncapped.max_mainpass_attempts_per_target = 0;
  const TracedPhotons a = trace_source_photons(scene, materials, emitter, planes, capped, 0);
  const TracedPhotons b = trace_source_photons(scene, materials, emitter, planes, uncapped, 0);
  const SourceTally& ta = a.tallies[0];
  const SourceTally& tb = b.tallies[0];
  EXPECT_TRUE(ta.capped);
  EXPECT_FALSE(tb.capped);
  EXPECT_LE(ta.mainpass_attempts, 256u * 200u);
  EXPECT_GT(tb.mainpass_attempts, 2 * 256u * 200u) << "the configuration is not low-yield enough";
  EXPECT_LT(ta.stored_global, 200u);
  EXPECT_GT(ta.stored_global, 0u);
  EXPECT_GE(double(tb.stored_global), 200.0 * (1 - 4 / std::sqrt(200.0)));
  // Identical pre-passes (the cap acts after them).
  EXPECT_EQ(ta.prepass_attempts, tb.prepass_attempts);
  EXPECT_DOUBLE_EQ(ta.flux_per_attempt * double(attempts_of(ta)), ta.bound_flux);
}

TEST(PhotonCap, CappedSourceFluxIsUnbiased) {
  // The capped main pass is a fixed number of i.i.d. attempts, each carrying
  // bound_flux / attempts, so the expected stored flux is that of the uncapped run. Each
  // run's stored flux is one sample; the standard error of a mean over independent seeds is
  // the sample standard deviation / sqrt(runs). Tolerance: 4 combined standard errors.
  // A 20 cm hole: yield ~1/60 per attempt; target 1000 needs ~60 000 attempts uncapped, the
  // cap at 8 per target photon allows 8000 after the pre-pass (~6400-12 800).
  const SceneDescription d = screened_window_room(0.2);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = low_sun();
  const PortEmitter emitter(scene, sources);
  TracingOptions o;
  o.photons_per_source = 1000;
  auto runs = [&](std::size_t cap, int count, std::uint64_t first_seed) {
    std::vector<double> flux;
    std::uint64_t capped = 0, stored = 0;
    for (int k = 0; k < count; ++k) {
      TracingOptions ok = o;
      ok.max_mainpass_attempts_per_target = cap;
      ok.seed = first_seed + std::uint64_t(k);
      const TracedPhotons t = trace_source_photons(scene, materials, emitter, planes, ok, 0);
      flux.push_back(stored_flux(t));
      capped += t.tallies[0].capped ? 1 : 0;
      stored += t.tallies[0].stored_global;
    }
    const double mean = std::accumulate(flux.begin(), flux.end(), 0.0) / double(count);
    double var = 0;
    for (double x : flux) var += (x - mean) * (x - mean);
    var /= double(count - 1);
    struct Stats { double mean, sd, se; std::uint64_t capped, stored; };
    return Stats{mean, std::sqrt(var), std::sqrt(var / double(count)), capped, stored};
  };
  const auto cap = runs(8, 48, 1000);
  const auto ref = runs(0, 12, 5000);
  EXPECT_EQ(cap.capped, 48u);
  EXPECT_EQ(ref.capped, 0u);
  EXPECT_LT(cap.stored * 12 * 2, ref.stored * 48) << "the cap did not halve the photons per run";
  EXPECT_NEAR(cap.mean, ref.mean, 4 * std::hypot(cap.se, ref.se))
      << "capped " << cap.mean << " +- " << cap.se << ", uncapped " << ref.mean << " +- " << ref.se;
  // Fewer photons, more variance per run (only for this source).
  EXPECT_GT(cap.sd, ref.sd);
  if (std::getenv("DAYPHOTON_TEST_VERBOSE"))  // numbers for docs/photon-tracing.md
    std::cout << "capped: " << cap.mean << " +- " << cap.se << " (sd " << cap.sd << ", "
              << cap.stored / 48 << " photons per run); uncapped: " << ref.mean << " +- " << ref.se
              << " (sd " << ref.sd << ", " << ref.stored / 12 << " photons per run)\n";
}

TEST(PhotonCap, UncappedSourcesAreBitIdenticalToNoCap) {
  // A cap of 2 attempts per target photon in the window room behind a screen with a 0.5 m
  // hole: the sky bins that see the port only through the hole store few photons per attempt
  // and are capped, the others must not change at all. (The bare window room capped 49 of 146
  // bins at 2 before the pane and the first event were weighted, docs/photon-tracing.md; now
  // every bin there stores about a photon per attempt or more and none is capped, even at 1.)
  const SceneDescription d = screened_window_room(0.5);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  TracingOptions none;
  none.photons_per_source = 300;
  none.max_mainpass_attempts_per_target = 0;
  TracingOptions tight = none;
  tight.max_mainpass_attempts_per_target = 2;
  std::size_t capped = 0, same = 0;
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const TracedPhotons a = trace_source_photons(scene, materials, emitter, planes, tight, p);
    if (a.tallies[0].capped) {
      ++capped;
      EXPECT_LE(a.tallies[0].mainpass_attempts, 2u * 300u) << "bin " << p;
      continue;
    }
    ++same;
    const TracedPhotons b = trace_source_photons(scene, materials, emitter, planes, none, p);
    EXPECT_EQ(attempts_of(a.tallies[0]), attempts_of(b.tallies[0])) << "bin " << p;
    EXPECT_FALSE(b.tallies[0].capped);
    ASSERT_EQ(a.surface.size(), b.surface.size()) << "bin " << p;
    ASSERT_EQ(a.planes[0].size(), b.planes[0].size()) << "bin " << p;
    EXPECT_EQ(0, std::memcmp(a.surface.data(), b.surface.data(), a.surface.size() * sizeof(Photon)));
    EXPECT_EQ(0, std::memcmp(a.planes[0].data(), b.planes[0].data(), a.planes[0].size() * sizeof(Photon)));
  }
  EXPECT_GT(capped, 0u);
  EXPECT_GT(same, 0u);
  if (std::getenv("DAYPHOTON_TEST_VERBOSE"))
    std::cout << "cap 2: " << capped << " sources capped, " << same << " unchanged\n";
}


// ---- accuracy rounds (photon_rounds.h) ----------------------------------------------------

// A round only adds photons: a source traced to 1500 attempts and then extended to 4000 holds
// exactly the photons (bit for bit, in the same order) and counts of one pass of 4000, for a
// sky bin in front of the window and for the ground; its scaled flux is bound_flux / 4000.
TEST(PhotonRounds, ExtendingASourceEqualsOnePassOfAllItsAttempts) {
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  TracingOptions o;
  o.seed = 7;
  for (const std::size_t source : {std::size_t(0), std::size_t(10)}) {
    SourcePhotonRecord rounds;
    extend_source_photons(scene, materials, emitter, planes, o, source, 1500, rounds);
    extend_source_photons(scene, materials, emitter, planes, o, source, 4000, rounds);
    SourcePhotonRecord once;
    extend_source_photons(scene, materials, emitter, planes, o, source, 4000, once);
    ASSERT_EQ(rounds.attempts, 4000u);
    ASSERT_GT(once.raw.planes[0].size(), 0u) << "source " << source;
    ASSERT_EQ(rounds.raw.surface.size(), once.raw.surface.size());
    ASSERT_EQ(rounds.raw.planes[0].size(), once.raw.planes[0].size());
    EXPECT_EQ(0, std::memcmp(rounds.raw.surface.data(), once.raw.surface.data(), once.raw.surface.size() * sizeof(Photon)));
    EXPECT_EQ(0, std::memcmp(rounds.raw.planes[0].data(), once.raw.planes[0].data(),
                             once.raw.planes[0].size() * sizeof(Photon)));
    EXPECT_EQ(rounds.raw.tallies[0].rays, once.raw.tallies[0].rays);
    EXPECT_EQ(rounds.stored(), once.stored());
    const TracedPhotons scaled = scaled_source_photons(rounds);
    EXPECT_DOUBLE_EQ(scaled.tallies[0].flux_per_attempt, emitter.bound_flux(std::uint32_t(source)) / 4000.0);
    EXPECT_FLOAT_EQ(scaled.planes[0][0].flux[1],
                    once.raw.planes[0][0].flux[1] * float(emitter.bound_flux(std::uint32_t(source)) / 4000.0));
  }
}

// The pilot driven step by step (next_pilot_attempts), each doubling traced in three ranges
// appended in order (as the ranks of an MPI run trace it), holds the photons, counts and
// attempts of pilot_source_photons, bit for bit.
TEST(PhotonRounds, ThePilotInRangesEqualsThePilotAtOnce) {
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  TracingOptions o;
  o.seed = 11;
  const std::size_t target = 2000;
  for (const std::size_t source : {std::size_t(0), std::size_t(10)}) {
    const SourcePhotonRecord once = pilot_source_photons(scene, materials, emitter, planes, o, source, target);
    SourcePhotonRecord ranged = empty_source_record(scene, materials, emitter, planes, source);
    int doublings = 0;
    while (const std::optional<std::uint64_t> next = next_pilot_attempts(ranged, target, o.max_prepass_attempts_per_target)) {
      ++doublings;
      const std::uint64_t a = ranged.attempts, b = *next;
      AttemptRange range;
      for (int k = 0; k < 3; ++k)
        append_attempt_range(range, round_attempt_range(scene, materials, emitter, planes, o, source, a + (b - a) * k / 3,
                                                        a + (b - a) * (k + 1) / 3));
      append_round_range(ranged, b, std::move(range));
    }
    EXPECT_GE(doublings, 2) << "source " << source;
    ASSERT_EQ(ranged.attempts, once.attempts);
    EXPECT_GE(ranged.raw.tallies[0].stored_global + ranged.raw.tallies[0].stored_caustic, target);
    ASSERT_EQ(ranged.raw.planes[0].size(), once.raw.planes[0].size());
    EXPECT_EQ(0, std::memcmp(ranged.raw.planes[0].data(), once.raw.planes[0].data(),
                             once.raw.planes[0].size() * sizeof(Photon)));
    EXPECT_EQ(ranged.raw.tallies[0].rays, once.raw.tallies[0].rays);
    EXPECT_EQ(ranged.raw.tallies[0].entered, once.raw.tallies[0].entered);
    EXPECT_EQ(ranged.stored(), once.stored());
  }
}

// The round's photons in one copy (scaled_merged_photons) are those of every record scaled
// (scaled_source_photons) and merged (merge_traced_photons), bit for bit, with the same tallies,
// and labelled by record when asked; a round then holds no per-source copies beside the merged
// one (docs/photon-tracing.md "Scale").
TEST(PhotonRounds, ScaledMergedPhotonsAreTheScaledSourcesMergedInOneCopy) {
  const SceneDescription d = window_room(MaterialType::Glass);
  const Scene scene = Scene::build(d);
  const std::vector<Material> materials = models_of(d);
  const std::vector<ReceiverPlane> planes = {work_plane(3, 4, 0.8), work_plane(3, 4, 1.2)};
  const SourceSet sources = SourceSet::sky_bins(sky::PatchBasis::tregenza());
  const PortEmitter emitter(scene, sources);
  TracingOptions o;
  o.seed = 13;
  o.store_direct_on_surfaces = true;
  // Two sky bins and the ground, each at its own attempts, and a record never traced.
  std::vector<SourcePhotonRecord> records;
  for (const std::size_t source : {std::size_t(10), std::size_t(140), std::size_t(0)}) {
    SourcePhotonRecord r = empty_source_record(scene, materials, emitter, planes, source);
    extend_source_photons(scene, materials, emitter, planes, o, source, 3000 + 500 * records.size(), r);
    records.push_back(std::move(r));
  }
  records.push_back(SourcePhotonRecord{});  // never traced: no tally, no planes
  for (const bool label : {false, true}) {
    std::vector<TracedPhotons> scaled;
    for (std::size_t p = 0; p < records.size(); ++p) {
      scaled.push_back(scaled_source_photons(records[p]));
      if (label) {
        for (Photon& ph : scaled.back().surface) ph.source = std::uint32_t(p);
        for (auto& plane : scaled.back().planes)
          for (Photon& ph : plane) ph.source = std::uint32_t(p);
      }
    }
    const TracedPhotons expected = merge_traced_photons(std::move(scaled));
    const TracedPhotons merged = scaled_merged_photons(records, label);
    ASSERT_GT(expected.surface.size(), 0u);
    ASSERT_EQ(merged.surface.size(), expected.surface.size());
    EXPECT_EQ(0, std::memcmp(merged.surface.data(), expected.surface.data(), expected.surface.size() * sizeof(Photon)));
    ASSERT_EQ(merged.planes.size(), expected.planes.size());
    for (std::size_t g = 0; g < planes.size(); ++g) {
      ASSERT_GT(expected.planes[g].size(), 0u) << "plane " << g;
      ASSERT_EQ(merged.planes[g].size(), expected.planes[g].size()) << "plane " << g;
      EXPECT_EQ(0, std::memcmp(merged.planes[g].data(), expected.planes[g].data(),
                               expected.planes[g].size() * sizeof(Photon)))
          << "plane " << g;
    }
    ASSERT_EQ(merged.tallies.size(), expected.tallies.size());
    for (std::size_t p = 0; p < expected.tallies.size(); ++p) {
      EXPECT_EQ(merged.tallies[p].prepass_attempts, expected.tallies[p].prepass_attempts);
      EXPECT_EQ(merged.tallies[p].stored_global, expected.tallies[p].stored_global);
      EXPECT_EQ(merged.tallies[p].rays, expected.tallies[p].rays);
      EXPECT_EQ(merged.tallies[p].flux_per_attempt, expected.tallies[p].flux_per_attempt);
      EXPECT_EQ(merged.tallies[p].bound_flux, expected.tallies[p].bound_flux);
    }
  }
}

}  // namespace
}  // namespace dayphoton::engine
