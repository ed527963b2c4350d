// The photon part under a continuous sky (photon_part_on_sky.h, sky_ratios.h).
//
// The closed-form case: a black room lit only through a vertical Lambertian diffuser (RADIANCE
// trans, all of its transmission diffuse) that faces the sky above a distant wall. Every photon leaves
// the diffuser in a direction independent of where it came from, and the room returns none, so
// the photon part on the work plane is proportional to the diffuser's irradiance, whatever the
// sky: its ratio under two skies is the ratio of the diffuser's vertical irradiances,
//   E_v = integral over the half space in front of the pane of L(w) (w . n) dw.
// Under the continuous CIE overcast sky that is one number; over the basis, each bin uniformly
// bright at its mean, another: the wall hides the lower half of the lowest band, whose radiance
// rises by 42 % toward its top, so the patch means understate what the pane sees. Both by midpoint
// quadrature here. The estimate's ratio photon_on_sky / (basis sum of the same coefficients) must
// match the continuous one within 4 standard errors over 48 seeds (|t| > 4 has probability
// 2.3e-4 with 47 degrees of freedom), and the basis's ratio, 1, must lie outside them (the test
// can fail). The stated variance of photon_on_sky over the observed one across the seeds must
// lie within the chi-square bounds of 47 degrees of freedom at 1e-3 two-sided (0.549-2.19).
#include "dayphoton/engine/photon_part_on_sky.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/engine_error.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/sky/patch_basis.h"
#include "diffuser_room.h"
#include "estimate_statistics.h"
#include "test_scenes.h"

namespace dayphoton::engine {
namespace {

using test::add_material;
using test::add_surface;

constexpr int Seeds = 48;
constexpr double GroundRadiance = 0.25;

/// CIE standard overcast sky (CIE S 011 / ISO 15469 type 1) with zenith radiance 1 above the
/// horizon, a uniform ground of GroundRadiance below it.
Vec3 overcast_with_ground(const Vec3& w) {
  const double l = w.z > 0.0 ? (1.0 + 2.0 * w.z) / 3.0 : GroundRadiance;
  return {l, l, l};
}

/// The same sky's mean in each bin of `basis`: uniform in sin(altitude) over a sky bin (equal
/// solid angle), so (1 + sin a0 + sin a1) / 3; the ground bin is uniform.
std::vector<Vec3> bin_means(const sky::PatchBasis& basis) {
  std::vector<Vec3> means(basis.bin_count());
  means[0] = {GroundRadiance, GroundRadiance, GroundRadiance};
  for (int p = 1; p < basis.bin_count(); ++p) {
    const sky::PatchBounds b = basis.bounds(p);
    const double l = (1.0 + std::sin(b.altitude_min_rad) + std::sin(b.altitude_max_rad)) / 3.0;
    means[std::size_t(p)] = {l, l, l};
  }
  return means;
}

using test::diffuser_room;
bool hidden(const Vec3& w) { return test::hidden_by_opposing_wall(w); }

/// The window's irradiance (normal +y) from a sky and from its bin means, the directions the
/// opposing wall hides left out, by midpoint quadrature over sin(altitude) and azimuth (equal
/// solid angles) in both hemispheres.
struct VerticalIrradiance {
  double continuous = 0, bin_means = 0;
};
VerticalIrradiance vertical_irradiance(const sky::PatchBasis& basis, const std::vector<Vec3>& means) {
  constexpr int Nu = 2000, Nphi = 2000;
  VerticalIrradiance e;
  const double du = 2.0 / Nu, dphi = 2 * Pi / Nphi;
  for (int i = 0; i < Nu; ++i) {
    const double z = -1.0 + (i + 0.5) * du, rho = std::sqrt(1 - z * z);
    for (int j = 0; j < Nphi; ++j) {
      const double phi = (j + 0.5) * dphi;
      const Vec3 w{rho * std::cos(phi), rho * std::sin(phi), z};
      if (w.y <= 0 || hidden(w)) continue;
      e.continuous += overcast_with_ground(w).x * w.y * du * dphi;
      e.bin_means += means[std::size_t(basis.find_bin(w))].x * w.y * du * dphi;
    }
  }
  return e;
}

std::vector<Material> models(const SceneDescription& d) {
  std::vector<Material> m;
  for (const MaterialSpec& spec : d.materials) m.push_back(Material::from_spec(spec));
  return m;
}

/// The coefficients of `sensors` on the plane z = 0 with the photon part on the sky.
DaylightCoefficients coefficients_with_sky(const Scene& scene, const std::vector<Material>& materials,
                                           const SourceSet& sources, const std::vector<SensorPoint>& sensors,
                                           const ContinuousSky& sky, const std::vector<Vec3>& means,
                                           std::uint64_t seed, CoefficientOptions o = {}) {
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.0, true, {{-3, -3}, {3, -3}, {3, 2}, {-3, 2}})};
  std::vector<double> luminance;
  for (const Vec3& l : means) luminance.push_back(luminance_of(l));
  TracingOptions t;
  t.photons_per_source = 1500;
  t.seed = seed;
  t.keep_surface_photons = false;
  t.sky_ratios = std::make_shared<const SkyRatios>(sky, luminance);
  TracedPhotons photons = trace_photons(scene, materials, sources, planes, t);
  const GridPhotons grid = GridPhotons::for_plane(planes[0], std::move(photons.planes[0]), sources.size());
  o.seed = seed;
  o.direct.seed = seed;
  o.direct.samples_per_source = 1;  // the direct part plays no role here
  o.photon_sky_bin_radiance_rgb = means;
  return daylight_coefficients(scene, materials, sources, grid, sensors, o);
}

double basis_sum(const DaylightCoefficients& c, std::size_t s, const std::vector<Vec3>& means) {
  double e = 0;
  for (std::size_t p = 0; p < c.sources; ++p)
    e += luminance_of(mul(c.caustic[s * c.sources + p] + c.global[s * c.sources + p], means[p]));
  return e;
}

/// The diffuser room on the Tregenza basis, with the sky's bin means.
struct DiffuserRoom {
  SceneDescription d = diffuser_room();
  Scene scene = Scene::build(d);
  std::vector<Material> materials = models(d);
  sky::PatchBasis basis = sky::PatchBasis::tregenza();
  SourceSet sources = SourceSet::sky_bins(basis);
  std::vector<Vec3> means = bin_means(basis);
};

TEST(PhotonPartOnSky, BehindADiffuserItIsTheContinuousSkysShareOfTheBasisSum) {
  const DiffuserRoom room;
  const Scene& scene = room.scene;
  const std::vector<Material>& materials = room.materials;
  const sky::PatchBasis& basis = room.basis;
  const SourceSet& sources = room.sources;
  const std::vector<Vec3>& means = room.means;
  const VerticalIrradiance e = vertical_irradiance(basis, means);
  const double expected = e.continuous / e.bin_means;
  RecordProperty("continuous_over_bin_means", std::to_string(expected));
  const ContinuousSky sky{"CIE overcast with a ground of 0.25", overcast_with_ground};
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{-2, -2, 0}, {0, 0, 1}}, {{1.5, 1.2, 0}, {0, 0, 1}}};
  std::vector<test::Stats> ratio(sensors.size()), on_sky(sensors.size());
  std::vector<double> stated(sensors.size(), 0.0);
  for (int k = 0; k < Seeds; ++k) {
    const DaylightCoefficients c =
        coefficients_with_sky(scene, materials, sources, sensors, sky, means, 7000 + std::uint64_t(k));
    ASSERT_EQ(c.photon_on_sky.irradiance.size(), sensors.size());
    EXPECT_EQ(c.photon_on_sky.basis_rows, 0u);
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      const double y = luminance_of(c.photon_on_sky.irradiance[s]);
      ratio[s].add(y / basis_sum(c, s, means));
      on_sky[s].add(y);
      stated[s] += c.photon_on_sky.variance[s] / Seeds;
    }
  }
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    RecordProperty("sensor_" + std::to_string(s) + "_ratio", std::to_string(ratio[s].mean()));
    EXPECT_NEAR(ratio[s].mean(), expected, ratio[s].tolerance()) << "sensor " << s;
    EXPECT_GT(std::fabs(1.0 - expected), ratio[s].tolerance()) << "sensor " << s << ": the basis would pass";
    const double observed = on_sky[s].sigma() * on_sky[s].sigma();
    EXPECT_GT(stated[s] / observed, 0.549) << "sensor " << s;
    EXPECT_LT(stated[s] / observed, 2.19) << "sensor " << s;
  }
}

TEST(PhotonPartOnSky, ASkyUniformInEachBinGivesTheBasisSumItself) {
  // Every ratio is exactly 1 (code SkyRatioOne), so the estimate on the sky is the basis sum
  // of the same coefficients up to the order of summation.
  const DiffuserRoom room;
  const std::vector<Vec3>& means = room.means;
  const sky::PatchBasis& basis = room.basis;
  const ContinuousSky stepped{"the bin means", [&](const Vec3& w) { return means[std::size_t(basis.find_bin(w))]; }};
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{-2, -2, 0}, {0, 0, 1}}};
  const DaylightCoefficients c =
      coefficients_with_sky(room.scene, room.materials, room.sources, sensors, stepped, means, 3);
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    const double basis_e = basis_sum(c, s, means);
    ASSERT_GT(basis_e, 0);
    EXPECT_NEAR(luminance_of(c.photon_on_sky.irradiance[s]), basis_e, 1e-12 * basis_e);
    double v = 0;
    for (std::size_t p = 0; p < c.sources; ++p)
      v += luminance_of(means[p]) * luminance_of(means[p]) * c.photon_variance[s * c.sources + p];
    EXPECT_NEAR(c.photon_on_sky.variance[s], v, 1e-12 * v);
  }
}

TEST(PhotonPartOnSky, EveryEstimatorPathWeightsByTheRatio) {
  // A sky of 1.5 times the bin means: every ratio is exactly 1.5 (code 3072), so on every
  // estimator path (the local-linear plane with the pilot correction, the quadratic fit, the
  // clipped-disc average, a caustic map of its own, the bias-compensating operator, the
  // contribution estimate) the estimate on the sky is 1.5 times the basis sum of the same
  // coefficients: a path that ignored the ratio would give 1.
  const DiffuserRoom room;
  const std::vector<Vec3>& means = room.means;
  const sky::PatchBasis& basis = room.basis;
  const ContinuousSky brighter{"1.5 x the bin means",
                               [&](const Vec3& w) { return means[std::size_t(basis.find_bin(w))] * 1.5; }};
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{-2, -2, 0}, {0, 0, 1}}, {{2.9, 1.9, 0}, {0, 0, 1}}};
  std::vector<std::pair<std::string, CoefficientOptions>> paths(7);
  paths[0].first = "default";
  paths[1].first = "quadratic curvature";
  paths[1].second.curvature_correction = CurvatureCorrection::Quadratic;
  paths[2].first = "clipped-disc average";
  paths[2].second.local_linear = false;
  paths[3].first = "caustic map";
  paths[3].second.caustic_bandwidth = 20;
  paths[4].first = "bias compensation";
  paths[4].second.local_linear = false;
  paths[4].second.bias_compensation = true;
  paths[5].first = "contribution";
  paths[5].second.estimator = PhotonEstimator::Contribution;
  paths[6].first = "contribution, bias compensation";
  paths[6].second.estimator = PhotonEstimator::Contribution;
  paths[6].second.bias_compensation = true;
  for (const auto& [name, options] : paths) {
    const DaylightCoefficients c =
        coefficients_with_sky(room.scene, room.materials, room.sources, sensors, brighter, means, 5, options);
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      const double basis_e = basis_sum(c, s, means);
      ASSERT_GT(basis_e, 0) << name;
      EXPECT_NEAR(luminance_of(c.photon_on_sky.irradiance[s]), 1.5 * basis_e, 1e-9 * basis_e)
          << name << ", sensor " << s;
    }
  }
}

/// The photon part on the sky by a second pass over the lookups: the rows estimated again with
/// density.flux = TimesSkyRatio, then summed (photon_part_on_sky_of).
PhotonOnSky second_pass_on_sky(const GridPhotons& grid, const std::vector<SensorPoint>& sensors,
                               const CoefficientOptions& options, const DaylightCoefficients& basis,
                               const std::vector<Vec3>& means) {
  DaylightCoefficients weighted;
  weighted.sensors = sensors.size();
  weighted.sources = basis.sources;
  weighted.caustic.assign(weighted.sensors * weighted.sources, Vec3{0, 0, 0});
  weighted.global.assign(weighted.sensors * weighted.sources, Vec3{0, 0, 0});
  CoefficientOptions o = options;
  o.density.flux = PhotonFlux::TimesSkyRatio;
  estimate_photon_coefficients(grid, sensors, o, weighted);
  return photon_part_on_sky_of(grid, sensors, basis, &weighted, means);
}

TEST(PhotonPartOnSky, OnePassOverTheLookupsGivesTheSecondPassBitForBit) {
  // daylight_coefficients sums both fluxes over the same lookups; a second pass estimates
  // again with density.flux = TimesSkyRatio: the same values, bit for bit, on every path.
  const DiffuserRoom room;
  const ContinuousSky sky{"CIE overcast with a ground of 0.25", overcast_with_ground};
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.0, true, {{-3, -3}, {3, -3}, {3, 2}, {-3, 2}})};
  std::vector<double> luminance;
  for (const Vec3& l : room.means) luminance.push_back(luminance_of(l));
  TracingOptions t;
  t.photons_per_source = 400;
  t.seed = 11;
  t.keep_surface_photons = false;
  t.sky_ratios = std::make_shared<const SkyRatios>(sky, luminance);
  TracedPhotons photons = trace_photons(room.scene, room.materials, room.sources, planes, t);
  const GridPhotons grid = GridPhotons::for_plane(planes[0], std::move(photons.planes[0]), room.sources.size());
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{-2.9, -2.9, 0}, {0, 0, 1}}, {{2.9, 1.9, 0}, {0, 0, 1}}};
  std::vector<CoefficientOptions> paths(6);
  paths[1].curvature_correction = CurvatureCorrection::Quadratic;
  paths[1].quadratic_fit_sources = {0, 5, 17};
  paths[2].local_linear = false;
  paths[3].caustic_bandwidth = 20;
  paths[4].local_linear = false;
  paths[4].bias_compensation = true;
  paths[5].estimator = PhotonEstimator::Contribution;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    CoefficientOptions o = paths[k];
    o.direct.samples_per_source = 1;
    o.photon_sky_bin_radiance_rgb = room.means;
    const DaylightCoefficients c = daylight_coefficients(room.scene, room.materials, room.sources, grid, sensors, o);
    const PhotonOnSky two = second_pass_on_sky(grid, sensors, o, c, room.means);
    ASSERT_EQ(c.photon_on_sky.irradiance.size(), sensors.size());
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      EXPECT_EQ(c.photon_on_sky.irradiance[s].x, two.irradiance[s].x) << "path " << k << ", sensor " << s;
      EXPECT_EQ(c.photon_on_sky.irradiance[s].z, two.irradiance[s].z) << "path " << k << ", sensor " << s;
      EXPECT_EQ(c.photon_on_sky.variance[s], two.variance[s]) << "path " << k << ", sensor " << s;
    }
  }
}

/// The gather photons of `room` (Direct ones on the surfaces) with the sky ratios of `sky`,
/// and the photon part of `sensors` by final gather, on that sky too unless `without_ratios`
/// (then the gathered rows keep the basis sum).
DaylightCoefficients gathered_with_sky(const Scene& scene, const std::vector<Material>& materials,
                                       const SourceSet& sources, const std::vector<Vec3>& means,
                                       const std::vector<SensorPoint>& sensors, const ContinuousSky& sky,
                                       std::uint64_t seed, int rays, bool without_ratios = false,
                                       std::size_t photons_per_source = 1500, bool quadrants = false) {
  std::vector<double> luminance;
  for (const Vec3& l : means) luminance.push_back(luminance_of(l));
  const auto ratios = std::make_shared<const SkyRatios>(sky, luminance);
  TracingOptions t;
  t.photons_per_source = photons_per_source;
  t.seed = seed;
  t.keep_surface_photons = true;
  t.store_direct_on_surfaces = true;
  t.sky_ratios = ratios;
  // The work plane too: its photons (the global ones) end each source's tracing at its target,
  // which the surfaces of a black room would never reach; the gather reads the surfaces'.
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.0, true, {{-3, -3}, {3, -3}, {3, 2}, {-3, 2}})};
  TracedPhotons photons = trace_photons(scene, materials, sources, planes, t);
  const GridPhotons grid = GridPhotons::for_gather(std::move(photons.surface), sources.size());
  CoefficientOptions o;
  o.gather.rays_per_sensor = rays;
  o.gather.seed = seed;
  o.gather.variance_weights = luminance;
  o.photon_sky_bin_radiance_rgb = means;
  if (!without_ratios) o.photon_sky_ratios = ratios;
  o.photon_quadrants = quadrants;
  DaylightCoefficients c;
  c.sensors = sensors.size();
  c.sources = sources.size();
  photon_coefficients(scene, materials, sources, grid, sensors, o, c);
  return c;
}

/// The diffuser room with the window an opening (the port) and the diffuser a surface
/// InnerDiffuserGap_m inside it: the photons that land on the diffuser from the sky are stored
/// there (Direct) for a final gather to read. The gap is a few ray offsets (the scene's 5 km
/// wall makes them 5 cm: Scene::ray_epsilon_m).
constexpr double InnerDiffuserGap_m = 0.15;

/// The inner diffuser's mean irradiance from a sky and from its bin means: at NxN_z midpoints of
/// the pane, the directions that pass the opening and that the opposing wall does not hide,
/// by midpoint quadrature as vertical_irradiance.
VerticalIrradiance inner_diffuser_irradiance(const sky::PatchBasis& basis, const std::vector<Vec3>& means) {
  constexpr int Nu = 600, Nphi = 600, Nx = 6, Nz = 3;
  VerticalIrradiance e;
  const double du = 2.0 / Nu, dphi = 2 * Pi / Nphi;
  for (int i = 0; i < Nu; ++i) {
    const double z = -1.0 + (i + 0.5) * du, rho = std::sqrt(1 - z * z);
    for (int j = 0; j < Nphi; ++j) {
      const double phi = (j + 0.5) * dphi;
      const Vec3 w{rho * std::cos(phi), rho * std::sin(phi), z};
      if (w.y <= 0 || hidden(w)) continue;
      const double t = InnerDiffuserGap_m / w.y;
      int open = 0;  // pane points that see direction w through the opening
      for (int a = 0; a < Nx; ++a)
        for (int b = 0; b < Nz; ++b) {
          const double x = -1.0 + 2.0 * (a + 0.5) / Nx + t * w.x, zz = 0.5 + (b + 0.5) / Nz + t * w.z;
          open += x >= -1 && x <= 1 && zz >= 0.5 && zz <= 1.5;
        }
      e.continuous += open * overcast_with_ground(w).x * w.y * du * dphi;
      e.bin_means += open * means[std::size_t(basis.find_bin(w))].x * w.y * du * dphi;
    }
  }
  return e;
}

struct InnerDiffuserRoom {
  SceneDescription d = [] {
    SceneDescription d = diffuser_room();
    const int pane = 1;  // the diffuser (diffuser_room's second material)
    const int opening = add_material(d, "opening", MaterialType::Opening, 0.0);
    for (Surface& s : d.surfaces)
      if (s.name == "window") s.material = opening;
    add_surface(d, "diffuser", pane, test::rect_at_y(2 - InnerDiffuserGap_m, -1, 1, 0.5, 1.5));
    return d;
  }();
  Scene scene = Scene::build(d);
  std::vector<Material> materials = models(d);
  sky::PatchBasis basis = sky::PatchBasis::tregenza();
  SourceSet sources = SourceSet::sky_bins(basis);
  std::vector<Vec3> means = bin_means(basis);
};

// The closed form of the first test on rows a final gather estimates (point sensors in mid-air
// and on a wall): every gather ray that meets the diffuser reads the Direct photons on its sky
// side, each flux times its ratio (final_gather.h, "The continuous sky"), so the gathered photon
// part on the sky over its basis sum is again E_v(continuous) / E_v(bin means), over the
// directions the diffuser sees through the opening (inner_diffuser_irradiance). 4 standard
// errors over 32 seeds (|t| > 4 has probability 3.7e-4 with 31 degrees of freedom); the basis's
// ratio 1 outside them; the stated variance over the observed one within the chi-square bounds
// of 31 degrees of freedom at 1e-3 two-sided (0.456-2.45).
TEST(PhotonPartOnSky, GatheredRowsBehindADiffuserTakeTheContinuousSkysShare) {
  constexpr int GatherSeeds = 32;
  const InnerDiffuserRoom room;
  const VerticalIrradiance e = inner_diffuser_irradiance(room.basis, room.means);
  const double expected = e.continuous / e.bin_means;
  RecordProperty("continuous_over_bin_means", std::to_string(expected));
  const ContinuousSky sky{"CIE overcast with a ground of 0.25", overcast_with_ground};
  const std::vector<SensorPoint> sensors = {
      {{0, 0, 0}, {0, 0, 1}}, {{-1.5, -1, 0.5}, {0, 1, 1}}, {{0.5, -2.99, 1.0}, {0, 1, 0}}};
  std::vector<test::Stats> ratio(sensors.size()), on_sky(sensors.size());
  std::vector<double> stated(sensors.size(), 0.0);
  for (int k = 0; k < GatherSeeds; ++k) {
    const DaylightCoefficients c = gathered_with_sky(room.scene, room.materials, room.sources, room.means, sensors,
                                                     sky, 9000 + std::uint64_t(k), 256);
    ASSERT_EQ(c.photon_on_sky.irradiance.size(), sensors.size());
    ASSERT_EQ(c.photon_on_sky.variance.size(), sensors.size());
    EXPECT_EQ(c.photon_on_sky.basis_rows, 0u);
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      const double y = luminance_of(c.photon_on_sky.irradiance[s]);
      const double b = basis_sum(c, s, room.means);
      ASSERT_GT(b, 0) << "sensor " << s;
      ratio[s].add(y / b);
      on_sky[s].add(y);
      stated[s] += c.photon_on_sky.variance[s] / GatherSeeds;
    }
  }
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    RecordProperty("gathered_sensor_" + std::to_string(s) + "_ratio", std::to_string(ratio[s].mean()));
    EXPECT_NEAR(ratio[s].mean(), expected, ratio[s].tolerance()) << "sensor " << s;
    EXPECT_GT(std::fabs(1.0 - expected), ratio[s].tolerance()) << "sensor " << s << ": the basis would pass";
    const double observed = on_sky[s].sigma() * on_sky[s].sigma();
    EXPECT_GT(stated[s] / observed, 0.456) << "sensor " << s;
    EXPECT_LT(stated[s] / observed, 2.45) << "sensor " << s;
  }
}

/// A room of grey walls, a mirror floor and a clear glass window (the port): a gather ray
/// that the mirror sends out through the glass leaves specularly to the sky (the caustic
/// part), and one that meets a wall reads its photons (the global part).
struct MirrorRoom {
  SceneDescription d = [] {
    SceneDescription d;
    const int grey = add_material(d, "grey", MaterialType::Lambertian, 0.5);
    const int glass = add_material(d, "glass", MaterialType::Glass, 0.0);
    const int mirror = add_material(d, "mirror", MaterialType::Mirror, 0.9);
    test::add_window_room(d, grey, glass);
    d.surfaces[0].material = mirror;  // the floor
    return d;
  }();
  Scene scene = Scene::build(d);
  std::vector<Material> materials = models(d);
  sky::PatchBasis basis = sky::PatchBasis::tregenza();
  SourceSet sources = SourceSet::sky_bins(basis);
  std::vector<Vec3> means = bin_means(basis);
};

TEST(PhotonPartOnSky, AGatheredRowsPathsToTheSkyAndLookupsBothTakeTheRatio) {
  // A sky of 1.5 times the bin means: every photon's ratio and every path's ratio to the sky
  // is 1.5, so the gathered rows' photon part on the sky is 1.5 times the basis sum of the
  // same coefficients, caustic (specular paths to the sky) and global (lookups) alike: a path
  // that ignored the ratio would give 1. The basis coefficients are those of a gather without
  // the sky bit for bit (the ratios draw no random numbers), which then keeps the basis sum
  // and counts its rows; one thread or two give the same bits.
  const MirrorRoom room;
  const sky::PatchBasis& basis = room.basis;
  const std::vector<Vec3>& means = room.means;
  const ContinuousSky brighter{"1.5 x the bin means",
                               [&](const Vec3& w) { return means[std::size_t(basis.find_bin(w))] * 1.5; }};
  const std::vector<SensorPoint> sensors = {{{0, 1, -0.5}, {0, 0, -1}}, {{0.5, -1, 0}, {0, 0, 1}}};
  auto run = [&](int threads, bool without_ratios) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism, threads);
    return gathered_with_sky(room.scene, room.materials, room.sources, means, sensors, brighter, 5, 64, without_ratios, 300);
  };
  const DaylightCoefficients c = run(2, false);
  EXPECT_EQ(c.photon_on_sky.basis_rows, 0u);
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    double caustic = 0, global = 0;
    for (std::size_t p = 0; p < c.sources; ++p) {
      caustic += luminance_of(c.caustic[s * c.sources + p]);
      global += luminance_of(c.global[s * c.sources + p]);
    }
    if (s == 0) {
      EXPECT_GT(caustic, 0) << "the sensor facing the mirror";
    }
    EXPECT_GT(global, 0) << "sensor " << s;
    const double basis_e = basis_sum(c, s, means);
    EXPECT_NEAR(luminance_of(c.photon_on_sky.irradiance[s]), 1.5 * basis_e, 1e-9 * basis_e) << "sensor " << s;
    EXPECT_GT(c.photon_on_sky.variance[s], 0) << "sensor " << s;
  }
  const DaylightCoefficients one = run(1, false), without = run(2, true);
  EXPECT_EQ(one.caustic, c.caustic);
  EXPECT_EQ(one.global, c.global);
  EXPECT_EQ(one.photon_on_sky.irradiance, c.photon_on_sky.irradiance);
  EXPECT_EQ(one.photon_on_sky.variance, c.photon_on_sky.variance);
  EXPECT_EQ(without.caustic, c.caustic);
  EXPECT_EQ(without.global, c.global);
  EXPECT_EQ(without.photon_variance, c.photon_variance);
  EXPECT_EQ(without.photon_on_sky.basis_rows, sensors.size());
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    const double basis_e = basis_sum(c, s, means);
    EXPECT_NEAR(luminance_of(without.photon_on_sky.irradiance[s]), basis_e, 1e-12 * basis_e) << "sensor " << s;
  }
}

// The photon part's sub-patch shares (DaylightCoefficients::photon_quadrants; photon.h, "sky
// quadrant"). Under a sky uniform over each quadrant of each bin, L_pq, the shares give the
// photon part sum_p [sum_q<3 Q_pq L_pq + (lum C_p - sum_q<3 Q_pq) L_p3] (the annual product's
// correction, study/sub_patch_shares.h). Behind the diffuser that is the diffuser's irradiance
// from that sky over its irradiance from the same sky uniform over each bin at its mean, by
// midpoint quadrature. The test sky lights the lowest band alone, and of each of its bins only
// the upper quadrant with the lower azimuths (quadrant 2: radiance 2, mean 0.5): the opposing
// wall hides the band's lower half, so the diffuser sees that quadrant and its neighbour
// (quadrant 3) alike, and the ratio is about 2. With patch-uniform bins it would be 1, without
// the shares (the whole coefficient in quadrant 3) 0: both must lie outside 4 standard errors
// of the mean over the seeds.

/// The test sky's radiance in quadrant q of a bin of the lowest band, and its mean.
double quadrant_test_radiance(int q) { return q == 2 ? 2.0 : 0.0; }
constexpr double QuadrantTestMean = 0.5;
/// Whether bin p is in the lowest band (the test sky's).
bool in_test_band(const sky::PatchBasis& basis, int p) { return p > 0 && basis.bounds(p).altitude_min_rad < 1e-9; }

/// The diffuser's irradiance (normal +y) from the quadrant sky over that from its bin means (1),
/// the hidden directions and the ground left out; through the opening of InnerDiffuserRoom at
/// NxN_z pane points when `inner`.
double quadrant_sky_over_bin_means(const sky::PatchBasis& basis, bool inner) {
  const int Nu = inner ? 600 : 2000, Nphi = inner ? 600 : 2000, Nx = 6, Nz = 3;
  const double du = 1.0 / Nu, dphi = 2 * Pi / Nphi;
  double quadrants = 0, means = 0;
  for (int i = 0; i < Nu; ++i) {
    const double z = (i + 0.5) * du, rho = std::sqrt(1 - z * z);
    for (int j = 0; j < Nphi; ++j) {
      const double phi = (j + 0.5) * dphi;
      const Vec3 w{rho * std::cos(phi), rho * std::sin(phi), z};
      if (w.y <= 0 || hidden(w)) continue;
      double open = 1;
      if (inner) {
        const double t = InnerDiffuserGap_m / w.y;
        int n = 0;
        for (int a = 0; a < Nx; ++a)
          for (int b = 0; b < Nz; ++b) {
            const double x = -1.0 + 2.0 * (a + 0.5) / Nx + t * w.x, zz = 0.5 + (b + 0.5) / Nz + t * w.z;
            n += x >= -1 && x <= 1 && zz >= 0.5 && zz <= 1.5;
          }
        open = n;
      }
      const int p = basis.find_bin(w);
      if (!in_test_band(basis, p)) continue;
      quadrants += open * quadrant_test_radiance(basis.quadrant(p, w)) * w.y;
      means += open * QuadrantTestMean * w.y;
    }
  }
  return quadrants / means;
}

/// The shares' photon part under the quadrant sky over its basis sum under the bin means, at
/// sensor s.
double shares_over_basis(const DaylightCoefficients& c, const sky::PatchBasis& b, std::size_t s) {
  double with_shares = 0, basis = 0;
  for (std::size_t p = 1; p < c.sources; ++p) {
    if (!in_test_band(b, int(p))) continue;
    const std::size_t i = s * c.sources + p;
    const double lum = luminance_of(c.caustic[i] + c.global[i]);
    const float* q = c.photon_quadrants.data() + i * StoredQuadrants;
    double rest = lum;
    for (std::size_t k = 0; k < StoredQuadrants; ++k) {
      with_shares += double(q[k]) * quadrant_test_radiance(int(k));
      rest -= double(q[k]);
    }
    with_shares += rest * quadrant_test_radiance(3);
    basis += lum * QuadrantTestMean;
  }
  return with_shares / basis;
}

TEST(PhotonPartOnSky, SubPatchSharesReproduceASkyUniformOverEachQuadrant) {
  constexpr int ShareSeeds = 16;
  const DiffuserRoom room;
  const double expected = quadrant_sky_over_bin_means(room.basis, false);
  RecordProperty("quadrant_sky_over_bin_means", std::to_string(expected));
  const ContinuousSky sky{"CIE overcast with a ground of 0.25", overcast_with_ground};
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{-2, -2, 0}, {0, 0, 1}}, {{1.5, 1.2, 0}, {0, 0, 1}}};
  // The default path (local-linear plane with the pilot correction); every other path is
  // checked by EveryEstimatorPathSplitsByTheQuadrant.
  {
    CoefficientOptions o;
    o.photon_quadrants = true;
    std::vector<test::Stats> ratio(sensors.size());
    for (int k = 0; k < ShareSeeds; ++k) {
      const DaylightCoefficients c = coefficients_with_sky(room.scene, room.materials, room.sources, sensors, sky,
                                                           room.means, 7100 + std::uint64_t(k), o);
      ASSERT_EQ(c.photon_quadrants.size(), sensors.size() * c.sources * StoredQuadrants);
      for (std::size_t s = 0; s < sensors.size(); ++s) ratio[s].add(shares_over_basis(c, room.basis, s));
    }
    for (std::size_t s = 0; s < sensors.size(); ++s) {
      RecordProperty("sensor_" + std::to_string(s) + "_ratio", std::to_string(ratio[s].mean()));
      EXPECT_NEAR(ratio[s].mean(), expected, ratio[s].tolerance()) << "sensor " << s;
      EXPECT_GT(std::fabs(1.0 - expected), ratio[s].tolerance()) << "sensor " << s << ": the basis would pass";
      EXPECT_GT(std::fabs(quadrant_test_radiance(3) / QuadrantTestMean - expected), ratio[s].tolerance())
          << "sensor " << s << ": no shares would pass";
    }
  }
}

TEST(PhotonPartOnSky, EveryEstimatorPathSplitsByTheQuadrant) {
  // Photons whose quadrant is set to their source's index mod 4: each coefficient then lies
  // whole in that quadrant, so on every estimator path its share there is the coefficient's
  // luminance and its other stored shares 0 (up to rounding); a path that ignored the quadrant
  // would give 0 or the whole coefficient in every share.
  const DiffuserRoom room;
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.0, true, {{-3, -3}, {3, -3}, {3, 2}, {-3, 2}})};
  TracingOptions t;
  t.photons_per_source = 400;
  t.seed = 17;
  t.keep_surface_photons = false;
  TracedPhotons photons = trace_photons(room.scene, room.materials, room.sources, planes, t);
  for (Photon& ph : photons.planes[0]) ph.sky_quadrant = ph.source % 4;
  const GridPhotons grid = GridPhotons::for_plane(planes[0], std::move(photons.planes[0]), room.sources.size());
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{-2.9, -2.9, 0}, {0, 0, 1}}, {{2.9, 1.9, 0}, {0, 0, 1}}};
  std::vector<std::pair<std::string, CoefficientOptions>> paths(7);
  paths[0].first = "default";
  paths[1].first = "quadratic curvature";
  paths[1].second.curvature_correction = CurvatureCorrection::Quadratic;
  paths[1].second.quadratic_fit_sources = {0, 5, 17};
  paths[2].first = "clipped-disc average";
  paths[2].second.local_linear = false;
  paths[3].first = "caustic map";
  paths[3].second.caustic_bandwidth = 20;
  paths[4].first = "bias compensation";
  paths[4].second.local_linear = false;
  paths[4].second.bias_compensation = true;
  paths[5].first = "contribution";
  paths[5].second.estimator = PhotonEstimator::Contribution;
  paths[6].first = "contribution, bias compensation";
  paths[6].second.estimator = PhotonEstimator::Contribution;
  paths[6].second.bias_compensation = true;
  for (auto& [name, o] : paths) {
    o.direct.samples_per_source = 1;
    o.photon_quadrants = true;
    const DaylightCoefficients c = daylight_coefficients(room.scene, room.materials, room.sources, grid, sensors, o);
    ASSERT_EQ(c.photon_quadrants.size(), sensors.size() * c.sources * StoredQuadrants) << name;
    double largest = 0;
    for (std::size_t i = 0; i < c.caustic.size(); ++i) largest = std::max(largest, luminance_of(c.caustic[i] + c.global[i]));
    ASSERT_GT(largest, 0) << name;
    std::size_t whole = 0;
    for (std::size_t s = 0; s < sensors.size(); ++s)
      for (std::size_t p = 0; p < c.sources; ++p) {
        const std::size_t i = s * c.sources + p;
        const double lum = luminance_of(c.caustic[i] + c.global[i]);
        for (std::size_t q = 0; q < StoredQuadrants; ++q) {
          const double want = q == p % 4 ? lum : 0.0;
          EXPECT_NEAR(c.photon_quadrants[i * StoredQuadrants + q], want, 1e-5 * largest)
              << name << ", sensor " << s << ", source " << p << ", quadrant " << q;
        }
        whole += lum > 1e-3 * largest && p % 4 < StoredQuadrants;
      }
    EXPECT_GT(whole, 40u) << name;  // the check is not vacuous
  }
}

TEST(PhotonPartOnSky, GatheredSubPatchSharesReproduceASkyUniformOverEachQuadrant) {
  constexpr int ShareSeeds = 12;
  const InnerDiffuserRoom room;
  const double expected = quadrant_sky_over_bin_means(room.basis, true);
  RecordProperty("quadrant_sky_over_bin_means", std::to_string(expected));
  const ContinuousSky sky{"CIE overcast with a ground of 0.25", overcast_with_ground};
  const std::vector<SensorPoint> sensors = {{{0, 0, 0}, {0, 0, 1}}, {{0.5, -2.99, 1.0}, {0, 1, 0}}};
  std::vector<test::Stats> ratio(sensors.size());
  for (int k = 0; k < ShareSeeds; ++k) {
    const DaylightCoefficients c = gathered_with_sky(room.scene, room.materials, room.sources, room.means, sensors,
                                                     sky, 9100 + std::uint64_t(k), 256, false, 1500, true);
    ASSERT_EQ(c.photon_quadrants.size(), sensors.size() * c.sources * StoredQuadrants);
    for (std::size_t s = 0; s < sensors.size(); ++s) ratio[s].add(shares_over_basis(c, room.basis, s));
  }
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    RecordProperty("gathered_sensor_" + std::to_string(s) + "_ratio", std::to_string(ratio[s].mean()));
    EXPECT_NEAR(ratio[s].mean(), expected, ratio[s].tolerance()) << "sensor " << s;
    EXPECT_GT(std::fabs(1.0 - expected), ratio[s].tolerance()) << "sensor " << s << ": the basis would pass";
    EXPECT_GT(std::fabs(quadrant_test_radiance(3) / QuadrantTestMean - expected), ratio[s].tolerance())
        << "sensor " << s << ": no shares would pass";
  }
}

TEST(PhotonPartOnSky, EverySkyPhotonRecordsTheQuadrantItWasEmittedInto) {
  // Photons stored on the plane straight behind the diffuser carry their bin's quadrants in
  // about the shares of the bin's light the diffuser sees; the ground's are all 0, and a
  // photon's class byte keeps class and quadrant apart.
  const DiffuserRoom room;
  const std::vector<ReceiverPlane> planes = {ReceiverPlane(0.0, true, {{-3, -3}, {3, -3}, {3, 2}, {-3, 2}})};
  TracingOptions t;
  t.photons_per_source = 400;
  t.seed = 13;
  t.keep_surface_photons = false;
  const TracedPhotons photons = trace_photons(room.scene, room.materials, room.sources, planes, t);
  std::array<std::size_t, 4> count{};
  std::size_t ground = 0;
  for (const Photon& ph : photons.planes[0]) {
    if (ph.source == 0) {
      EXPECT_EQ(ph.sky_quadrant, 0u);
      ++ground;
      continue;
    }
    ++count[ph.sky_quadrant];
    EXPECT_EQ(ph.class_byte() & 3u, static_cast<unsigned>(ph.path_class));
    EXPECT_EQ(ph.class_byte() >> 2, unsigned(ph.sky_quadrant));
  }
  EXPECT_GT(ground, 0u);
  for (std::size_t q = 0; q < 4; ++q) EXPECT_GT(count[q], 0u) << "quadrant " << q;
}

TEST(PhotonPartOnSky, TheRatioCodeRoundsToNearestAndRefusesWhatItCannotHold) {
  EXPECT_EQ(Photon::sky_ratio_code_of(1.0), SkyRatioOne);
  EXPECT_EQ(Photon::sky_ratio_code_of(0.8301), 1700u);  // 1700.04
  EXPECT_EQ(Photon::sky_ratio_code_of(1.18 + 0.25 / 2048), 2417u);  // 2416.89 + 0.25
  EXPECT_TRUE(Photon::sky_ratio_fits(0.0));
  EXPECT_TRUE(Photon::sky_ratio_fits(4095.49 / 2048));
  EXPECT_FALSE(Photon::sky_ratio_fits(4095.5 / 2048));
  EXPECT_FALSE(Photon::sky_ratio_fits(-1e-9));
  EXPECT_FALSE(Photon::sky_ratio_fits(std::nan("")));
  Photon p;
  EXPECT_EQ(p.sky_ratio_code, SkyRatioOne);
  p.set_source_word(0xABC12345u);
  EXPECT_EQ(p.source, 0x12345u);
  EXPECT_EQ(p.sky_ratio_code, 0xABCu);
  EXPECT_EQ(p.source_word(), 0xABC12345u);
  // A sky twice as bright somewhere in a bin as its mean there has no code: an error, not a
  // silently clamped ratio.
  const SkyRatios ratios({"steep", [](const Vec3& w) { return Vec3{1, 1, 1} * (w.z > 0.5 ? 3.0 : 1.0); }},
                         std::vector<double>(146, 1.0));
  EXPECT_DOUBLE_EQ(ratios.ratio(5, {1, 0, 0.1}), 1.0);
  EXPECT_THROW(ratios.ratio(5, {0, 0, 1}), EngineError);
  EXPECT_THROW(ratios.ratio(146, {0, 0, 1}), std::out_of_range);
}

}  // namespace
}  // namespace dayphoton::engine
