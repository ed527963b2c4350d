// Final gather: the photon part of the daylight coefficients at a sensor that is not on a
// receiver plane (a RADIANCE .pts point in mid air, a vertical or tilted grid, a point on a
// black surface), from the sensor's own position and normal.
//
// The irradiance of the light that reaches sensor x (unit normal n) after at least one
// scattering event is
//
//   E(x) = integral over the hemisphere of n of L(x <- w) cos(w, n) dw
//        ~ pi / N sum_i L(x <- w_i),   w_i cosine-weighted, N = k x k stratified
//
// (Pharr, Jakob & Humphreys, "Physically Based Rendering", 4th ed., section A.5.3, Malley's
// method), the radiance along each gather ray being read off the photon maps where the ray
// first meets a surface with a diffuse component (Jensen, "Realistic Image Synthesis Using
// Photon Mapping", 2001, section 9.3.3, "final gathering"; RADIANCE's rcontrib does the same
// with a contribution photon map: R. Schregle, "Development and Integration of the RADIANCE
// Photon Map Extension", technical report, 2015, on contribution photon maps):
//
//   L(y -> x) = rho_d(y) / pi  E_photons(y, side facing x)
//             + tau_d(y) / pi  E_photons(y, the other side)         (translucent),
//
// so each gather ray adds rho_d E_p(y) / N to the coefficient of every source p, E_p(y)
// being the contribution estimate at y (density_estimate.h: the N_g nearest surface photons
// of ALL sources passing the side filter, binned by source). The surface photons here must
// include the DIRECT ones (TracingOptions::store_direct_on_surfaces): light that reached y
// straight from the sky and is reflected once toward x is indirect at x (on outdoor
// scatterers only on the sides a gather can reach: gathered_scatterer_sides.h). The lookups are
// noisy one by one (a few photons per source), but the N gather rays average them: the
// estimate's noise is that of the gather, and its bias the (small) kernel bias at y.
//
// Specular and glossy parts at a hit (mirrors, glass, metal, plastic's specular lobe) are
// followed by sampling the material (Material::sample, reciprocal in the forms used here),
// up to GatherOptions::max_specular_events; a path that leaves through a port after at least
// one such event reaches the source containing its direction (SourceSet::find) with unit
// radiance: that is the caustic part. Paths that leave without a specular event are the
// zero-event light of the direct component (shadow rays, direct_component.h) and are NOT
// counted here; a path that meets anything after its port is blocked (an outdoor scatterer
// excepted: its photons, direct ones included, are looked up and its specular events
// followed, as in the room; port_emission.h), and one that leaves
// without crossing a port carries nothing (the rule of direct_component.h), so every light
// path is counted once. Where the photon pass stores no photons (a black room), the gather
// adds only the specular paths, which is exactly the light there is.
//
// A sun disc (0.5 degrees) is reached by a specular gather path only with a probability of
// the order of its solid angle: a point sensor inside a sun beam redirected by a mirror
// gets that beam with high variance. Surfaces receive it through their caustic photons
// (a sensor on a surface, or a receiver plane, resolves it).
//
// Variance (estimate_variance.h). The estimate F = sum_h Z_h over the gather rays h has two
// random parts, the photons and the rays. Given the rays, F is linear in the photons, but one
// photon (and one light path, whose photons were stored one after the other on several
// surfaces) reaches the sensor along many rays: its terms are summed over all rays first, and
// the photons are grouped by path (PhotonGroups: runs of PathGroupPhotons consecutive
// photons of a source in tracing order; the groups are independent draws), so the photon part
// is the batch-means variance of the groups' sums, C/(C-1) (sum_c S_c^2 - S^2/C) with C the
// source's groups. The rays' part (the sampling of the directions, and of the specular paths
// to the sources: the caustic part) is the collapsed-strata variance (pairs of neighbouring
// strata) of the rays' values over all sources, shared among the sources by their part of
// each pair's values (a ray is shared by the sources: estimate_variance.h), less the photon
// noise those values carry, which the same formula applied to each group's per-ray sums S_hc
// estimates (that noise is in the photon part already). Their sum is clamped at 0.
// The strata are taken in rows of k: second differences of every run of three neighbours,
// (z1 - 2 z2 + z3)^2 / 6 times k / (k - 2) (StratifiedVariance, estimate_variance.h: a linear
// trend across the strata cancels); a row of two gives the pair's difference squared, one
// its square. A ray's value over all sources is a weighted sum, sum_p w_p z_p
// (GatherOptions::variance_weights: the daylight factor's sky), and source p's share of a
// run's variance V is V (w_p z_p / sum_q w_q z_q) / w_p^2, so that sum_p w_p^2 V_p is V:
// the variance of the sky-weighted sum is then that of its own rays. The rays are shared by
// the sources and their per-source values are not independent: with unit weights the shares
// summed under the overcast sky's luminances overstated the wall sensors' DF variance of
// projects/wall_sensors 1.8 times over (docs/photon-map.md, "Uncertainty").
//
// How the variance falls with the rays. With S_c = sum_h S_hc, the photon part's
// sum_c S_c^2 = sum_c sum_h S_hc^2 + sum_c sum_{h != h'} S_hc S_h'c: the first sum (each
// group's terms on one ray) has N terms of size 1/N^2, so it falls as 1/N; the second (a group
// read by two different rays) has N^2 pairs of size 1/N^2, each pair read with a probability
// that does not depend on N, so it stays: it is the part only more photons lower (rays are
// dense next to the lookup discs). fixed_photon_variance is the photon part less the first
// sum (the same C/(C-1) factor), clamped to [0, variance]. The rays' part falls at least as
// 1/N (stratification never raises the variance of the plain estimate: Veach, "Robust Monte
// Carlo Methods for Light Transport Simulation", PhD thesis, Stanford 1997, section 2.7.1). So
// at N' rays the variance is about fixed + (variance - fixed) N / N' (the accuracy target's
// gather rounds, study/gather_accuracy_rounds.h).
//
// The continuous sky (photon_part_on_sky.h). With a GatherOnSky, the same rays also estimate
// the photon part under the continuous sky the photons' sky ratios were taken from (sky_ratios.h),
// summed over the sources with the bin radiances L_p: at a lookup each photon's flux is taken
// times its ratio r = L(w) / L_p (PhotonFlux::TimesSkyRatio: the bin's response to the sky
// within it, sky_ratios.h), and a specular path that leaves toward source p in direction w
// carries r(w) exactly, the ratio the photon tracer would give a photon emitted from there
// (SkyRatios::ratio, before its 12-bit rounding). So every term of the basis estimate is
// weighted by the sky's own radiance where its light came from, E = sum_p L_p C'_p, and the
// estimate is the response to the continuous sky, free of the basis's patch-uniform radiance;
// the basis coefficients are the same bit for bit (the ratios draw no random numbers). Its
// variance is that of the same estimator (header comment, "Variance") with every term taken
// in its sky-weighted luminance, lum(term) r lum(L_p), and no further weights: the photons'
// part is the groups' batch means of those terms and the rays' part the collapsed strata of
// the rays' sky-weighted sums, so the sum over the sources is the variance of E itself.
//
// Determinism: gather ray i of sensor s uses Rng(seed, s, i, RandomStream::Gather); sensors
// are independent, so the result is identical for any thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/photon_map.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sensor_range.h"
#include "dayphoton/engine/sky_ratios.h"

namespace dayphoton::engine {

/// Consecutive stored photons of one source grouped for the gather's variance (header
/// comment): a path's photons are stored one after the other, so a group of this many holds
/// whole paths except at its ends.
constexpr std::size_t PathGroupPhotons = 64;

/// Which photons of a map come from the same paths (header comment, "Variance").
struct PhotonGroups {
  std::vector<std::uint32_t> group_of;          ///< per photon of the map (tree order)
  std::vector<std::uint32_t> source_of;         ///< per group
  std::vector<std::uint32_t> groups_of_source;  ///< per source
  /// Groups of `group_size` consecutive photons of one source, in the tracing order of
  /// `photons` (a new group also starts where the source changes); group_of in that order.
  static PhotonGroups consecutive(const std::vector<Photon>& photons, std::size_t sources,
                                  std::size_t group_size = PathGroupPhotons);
  /// Put group_of in the map's tree order: `tree_to_input` maps each photon of the built
  /// map to its index in the photons given to consecutive() (PhotonMap's second constructor).
  void to_tree_order(const std::vector<std::uint32_t>& tree_to_input);
};

struct GatherOptions {
  int rays_per_sensor = 1024;       ///< gather rays per sensor, >= 1; rounded up to a square
  std::size_t bandwidth = 32;       ///< photons per lookup at a gather hit (all sources), >= 1
  int max_specular_events = 16;     ///< specular/glossy events followed per gather ray
  std::uint64_t seed = 1;
  /// Per source, its weight in the sum whose rays' variance is measured (header comment,
  /// "Variance": the daylight factor's sky luminances); empty: 1 for every source. The
  /// photons' part does not depend on it.
  std::vector<double> variance_weights;
  /// Also the photon part's sub-patch shares (GatheredCoefficients::quadrants), for sources
  /// that are a basis's bins.
  bool sky_quadrants = false;
};

/// The continuous sky of the photons' sky ratios (header comment, "The continuous sky"):
/// `ratios`, those the photons were traced with (TracingOptions::sky_ratios);
/// `bin_radiance_rgb[p]`, source p's L_p, RGB W/(sr m^2). Sources that are not sky bins (sun
/// discs) take ratio 1, as their photons do.
struct GatherOnSky {
  const SkyRatios& ratios;
  const std::vector<Vec3>& bin_radiance_rgb;
};

/// Caustic (specular paths to a source) and global (photon lookups) parts, each
/// [sensor * sources + source], RGB W/m^2 per unit source radiance.
struct GatheredCoefficients {
  std::vector<Vec3> caustic, global;
  /// The variance of caustic + global's luminance (header comment), when groups were given.
  std::vector<double> variance;
  /// Of it, the photons' part that more gather rays do not reduce (header comment, "How the
  /// variance falls with the rays"), same layout, 0 <= fixed <= variance.
  std::vector<double> fixed_photon_variance;
  /// With a GatherOnSky: per row, the photon part (caustic + global) under its continuous
  /// sky, sum_p L_p C'_p, RGB W/m^2 (header comment, "The continuous sky"), and, when groups
  /// were given, the variance of its luminance. Empty otherwise.
  std::vector<Vec3> on_sky;
  std::vector<double> on_sky_variance;
  /// With GatherOptions::sky_quadrants: [row * sources * StoredQuadrants + p * StoredQuadrants
  /// + q], the luminance of (caustic + global)[row][p]'s part whose light came through
  /// quadrant q of bin p: the photons emitted into it (photon.h) and the specular paths that
  /// leave through it (daylight_coefficients.h, DaylightCoefficients::photon_quadrants).
  std::vector<float> quadrants;
};

/// The gather at every sensor. `surface_photons` is the map of every stored surface photon
/// of `sources` (Direct included). Parallel over sensors, deterministic. Throws
/// std::invalid_argument for rays_per_sensor < 1, bandwidth 0, a sensor normal that is zero
/// or not finite, or a photon whose source is not in `sources`. `rows`: only those sensors'
/// rows (sensor_range.h: the rays of a sensor are seeded by its index in the whole grid).
/// `on_sky`: the photon part under the continuous sky too (GatheredCoefficients::on_sky); also
/// throws std::invalid_argument when its radiances are not one per source or a sky bin of
/// `sources` has no ratio.
GatheredCoefficients gather_photon_coefficients(const Scene& scene,
                                                const std::vector<Material>& materials,
                                                const SourceSet& sources,
                                                const PhotonMap& surface_photons,
                                                const std::vector<SensorPoint>& sensors,
                                                const GatherOptions& options,
                                                const PhotonGroups* groups = nullptr,
                                                SensorRange rows = {}, const GatherOnSky* on_sky = nullptr);

/// The same at the sensors `which` (indices into `sensors`, any order): row r of the result is
/// sensor which[r], bit for bit that sensor's row of the whole grid's gather (its rays are
/// seeded by its index). Also throws std::invalid_argument for an index not within `sensors`.
GatheredCoefficients gather_photon_coefficients_at(const Scene& scene, const std::vector<Material>& materials,
                                                const SourceSet& sources, const PhotonMap& surface_photons,
                                                const std::vector<SensorPoint>& sensors,
                                                const GatherOptions& options, const PhotonGroups* groups,
                                                const std::vector<std::size_t>& which,
                                                const GatherOnSky* on_sky = nullptr);

}  // namespace dayphoton::engine
