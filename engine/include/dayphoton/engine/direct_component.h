// Direct component of the daylight coefficients (DESIGN.md section 5): for each sensor and
// each distant source, the irradiance from the source seen straight through the glazing,
// per unit source radiance:
//
//   C_direct[s][p] = integral over source p of T(x_s, w) max(0, dot(w, n_s)) dw
//
// where T is the product of the straight transmittances (Material::straight_transmittance:
// Fresnel-weighted thin glass, openings) of the surfaces the shadow ray from the sensor
// passes, up to and including the first PORT it crosses; anything opaque before the port,
// or any surface after it (external obstructions; there is no external inter-reflection)
// other than an outdoor scatterer's straight transmission (a glazed canopy: port emission
// leaves that light to the scatterer, whose photons stay Direct through it), makes T = 0,
// and so does a ray that leaves without crossing a port (photons enter only through
// ports). These are exactly the zero-event paths that the photon tracer does not
// store, so direct + photon estimates count every path once.
//
// The integral is estimated by stratified sampling of the source's solid angle
// (SourceSet::sample_direction on a jittered sqrt(n) x sqrt(n) grid, n rounded up to a
// square), independently seeded per (sensor, source) with
// Rng(seed, source index, sensor index, RandomStream::Direct). Two runs with the same seed
// therefore trace the same directions whatever the scene's materials, which makes
// glazed/unglazed comparisons exact ratios. The estimate of one (sensor, source) is
//
//   C = Omega_p / n * sum over strata of T(w_ij) max(0, dot(w_ij, n_s)),
//   w_ij = sample_direction(p, (i + xi) / k, (j + xi') / k),  k = ceil(sqrt(n)),
//
// unbiased, with variance (Omega_p / n)^2 * sum over strata of the stratum's variance of
// T cos: only strata cut by a shadow edge or spanning a large change of T cos contribute,
// so the error falls as n^(-3/4) at edges and n^(-1) or faster where T cos is smooth.
//
// Sampling through the ports (DirectOptions::port_sampling, the default). A sensor sees the
// sky only through the openings. Stratified over a source's solid angle alone, a source
// much larger than the opening seen from the sensor is hit or missed whole: the ground bin 0
// (2 pi sr) at 64 samples has strata of ~0.1 sr, and ceiling points of a black room came out
// from -100 % to +150 % of its closed-form component; a window seen from the back of a room
// (0.09 sr at 8 m) falls into two or three sky patches and gets ~35 of their samples (+-10 %).
// So every sensor also samples the ports: kb x kb stratified points y uniform by area over
// the ports (kb = PortStrataFactor x k, for each side of the sensor's height, below), whose
// direction w = (y - x) / |y - x| has the density n_b |y - x|^2 / (A |w . n_j|) per steradian
// (A the side's total port area; the change of
// variables d omega = |w . n_j| dA / d^2: Pharr, Jakob & Humphreys, "Physically Based
// Rendering", 4th ed., section 4.2.3), and is credited to the source containing it
// (SourceSet::find). The two strategies are combined by the balance heuristic (Veach &
// Guibas, "Optimally Combining Sampling Techniques for Monte Carlo Rendering", SIGGRAPH 1995;
// Veach's thesis, section 9.2): every sample of either strategy contributes
//
//   T(w) max(0, w . n_s) / (n_a / Omega_p + sum_j n_b t_j^2 / (A |w . n_j|)),
//
// the sum running over every port the ray from x along w crosses (t_j its distance), which is
// unbiased for every source (each strategy's density is positive wherever the other's is
// zero only where T = 0: a direction that crosses no port carries no light). The port points
// dominate where the opening is small against the source (the ground, a distant window), the
// source strata where it is large (a sky patch seen through a wide window nearby). The ports
// are sampled in two sides, their parts below and above the sensor's height (each side's
// points spread over its pieces by area, so the cost does not grow with the number of
// ports: a light pipe's dome has dozens of facets), so the horizon
// (the ground bin's boundary) never cuts a stratum (a horizontal cut through a window's
// strata gave +-3 % at 1024 points); a parallelogram with horizontal edges (a vertical or
// sloped window) keeps edge-aligned strata (Port::parallelogram), any other polygon is
// clipped into a fan of triangles. Sources below PortSampledMinimumSolidAngle_sr take no
// port samples (for them the two densities are not mixed). With
// port_sampling off, or in a scene without ports, the estimator is the plain one above.
// Rays per sensor: k^2 x sources + (PortStrataFactor k)^2 per side with ports (64 x samples).

// Continuous skies (DirectOptions::skies). A coefficient is per unit radiance of its source,
// so a sky-weighted sum sum_p C[s][p] L_p treats each sky patch as uniformly bright at its
// mean radiance L_p. Within a patch the sky is not: the CIE overcast sky's lowest
// 12-degree band rises from 1.0 to 1.42 times its horizon luminance, and a sensor sees only
// part of a patch through an opening, or weights it by its cosine, which correlates with the
// gradient. For a horizontal sensor that sees the whole lowest band the patch-uniform sum
// is 5.7 % low; for one that sees only its lower half (deep in a room) 6 % high. So the same
// samples also estimate the direct irradiance under each listed continuous sky,
//
//   D_k[s] = integral over all directions of L_k(w) T(x_s, w) max(0, dot(w, n_s)) dw,
//
// each sample's value per unit radiance times L_k at its own direction: the same unbiased
// estimator as the coefficients' (both strategies, the balance heuristic), with its variance
// by the same collapsed strata. It costs no shadow ray. A study whose sky is known (the
// daylight factor's CIE overcast sky) reads its sky component from D_k instead of the
// patch-uniform sum; the photon part stays on the basis.
//
// Sub-patch shares (direct_coefficients' `quadrants`). The annual sky matrix is one value per
// patch and hour, so the continuous sky cannot be used there; instead each sky bin's
// coefficient is split by where its samples lie: the luminance of the part of C[s][p] whose
// directions fall in each of the bin's four quadrants (sky::PatchBasis::quadrant: halves in
// sine of altitude and in azimuth). A source stratum's quadrant is that of its numbers
// (u1, u2), exact for an even k (an odd k's middle strata are split by their sample); a port
// point's is found from its direction. Each is the same unbiased estimator restricted to a
// quadrant, so sum_q Q_pq L_pq is the direct irradiance of a sky that is uniform within each
// quadrant, and the annual product adds sum_q Q_pq (L_pq - L_p) to the patch-uniform sum
// (study/annual_illuminance.h). No shadow ray is added: one addition per sample.

// Shadow rays start at the sensor moved ray_epsilon_m() along its normal (only directions
// with dot(w, n_s) > 0 are traced), so a sensor lying on a surface does not see that
// surface. A ray that would have to cross more than MaxShadowRayCrossings surfaces is
// treated as blocked (a guard against pathological stacks; real glazing has a few panes).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/continuous_sky.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_range.h"

namespace dayphoton::engine {

/// Surfaces a shadow ray may pass before it counts as blocked (see the header comment).
constexpr int MaxShadowRayCrossings = 1000;
/// Port points per axis of each side, per stratum of a source (header comment): the ports'
/// parts below and above the sensor's height each get 64 x samples_per_source points.
constexpr int PortStrataFactor = 8;
/// Sources smaller than this (sun discs: 6.8e-5 sr; Reinhart patches above MF 6) are sampled
/// over their own solid angle only: port points would hit them a few times per sensor, each
/// hit carrying a large share of the estimate (header comment).
constexpr double PortSampledMinimumSolidAngle_sr = 1e-3;

/// A shadow ray's way to the sky: the straight transmittance under the rule above (zero if
/// blocked), and the port it crossed first (-1 if none, then the transmittance is zero).
struct SkyPath {
  Vec3 transmittance;
  int port = -1;
};

struct DirectOptions {
  int samples_per_source = 64;  ///< shadow rays per (sensor, source), >= 1; rounded up to a square
  std::uint64_t seed = 1;
  /// Also sample the ports and combine by the balance heuristic (header comment); off: the
  /// plain solid-angle estimator (whose variance has the closed form given above).
  bool port_sampling = true;
  /// The direct irradiance under each of these skies is estimated from the same samples
  /// (header comment, "Continuous skies"; direct_coefficients' `on_skies`).
  std::vector<ContinuousSky> skies;
};

/// The direct irradiance of every sensor under each sky of DirectOptions::skies: [row *
/// skies + k], RGB W/m^2, and the variance of its luminance (the same collapsed strata as the
/// coefficients').
struct DirectOnSkies {
  std::size_t skies = 0;
  std::vector<Vec3> irradiance;
  std::vector<double> variance;
};

/// Quadrant shares are kept for the first three quadrants: the fourth is the coefficient's
/// luminance less their sum.
constexpr std::size_t StoredQuadrants = 3;

/// Transmittance (RGB) from `origin` along `direction` (unit, toward the sky) to the sky
/// under the rule above. `materials[m]` is the model of scene material m (built by the
/// caller with Material::from_spec from SceneDescription::materials, same order). The ray
/// starts at `origin` with tmin = 0: offset it first if it lies on a surface.
/// Throws std::invalid_argument if `materials` has fewer entries than the description.
Vec3 sky_transmittance(const Scene& scene, const std::vector<Material>& materials,
                       const Vec3& origin, const Vec3& direction);
/// The same, with the port the ray crossed first.
SkyPath trace_to_sky(const Scene& scene, const std::vector<Material>& materials,
                     const Vec3& origin, const Vec3& direction);

/// C_direct for every sensor (rows) and source (columns): result[s * sources.size() + p],
/// RGB, W/m^2 per unit radiance (W/m^2/sr). Parallel over sensors (oneTBB); every entry
/// depends only on (scene, materials, source p, sensor s, options), so the result is
/// identical for any thread count. Throws std::invalid_argument for samples_per_source < 1,
/// a sensor normal that is zero or not finite, or too few materials. `variance`, if given,
/// receives the same layout: the collapsed-strata variance of each entry's luminance
/// (estimate_variance.h), both strategies' strata added (they are independent); the
/// estimates themselves do not change. `rows`: only those sensors' rows (sensor_range.h:
/// random numbers by the index in the whole of `sensors`, so they equal the whole result's rows).
/// `on_skies`, if given, receives the rows' direct irradiance under options.skies (header
/// comment, "Continuous skies"), from the very samples of the coefficients. `quadrants`, if
/// given and the sources are a basis's bins (SourceSet::has_basis), receives [row * sources *
/// StoredQuadrants + p * StoredQuadrants + q]: the luminance of C[s][p]'s part in quadrant q
/// of sky bin p (header comment, "Sub-patch shares"; zero for the ground bin); otherwise it is
/// emptied.
std::vector<Vec3> direct_coefficients(const Scene& scene, const std::vector<Material>& materials,
                                      const SourceSet& sources,
                                      const std::vector<SensorPoint>& sensors,
                                      const DirectOptions& options,
                                      std::vector<double>* variance = nullptr,
                                      SensorRange rows = {}, DirectOnSkies* on_skies = nullptr,
                                      std::vector<float>* quadrants = nullptr);

/// Direct irradiance at one sensor from a continuous sky radiance function
/// (direction toward the sky -> RGB radiance), integrated over the sources of `sources`
/// (the whole sphere when they are the bins of a basis, which partition it) with `samples`
/// stratified directions per source, seeded as sensor index 0 of direct_coefficients: with
/// the same seed and sample count it traces the very directions of sensor 0's
/// coefficients, so sum_p C[0][p] L_p and this integral differ only by the radiance
/// variation inside each source (used to check that the coefficients are linear).
/// `port_sampling` as DirectOptions::port_sampling.
Vec3 direct_irradiance(const Scene& scene, const std::vector<Material>& materials,
                       const SourceSet& sources, const SensorPoint& sensor,
                       const std::function<Vec3(const Vec3&)>& radiance, int samples,
                       std::uint64_t seed, bool port_sampling = true);

}  // namespace dayphoton::engine
