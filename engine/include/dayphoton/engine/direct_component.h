// Direct component of the daylight coefficients (DESIGN.md section 5): for each sensor and
// each distant source, the irradiance from the source seen straight through the glazing,
// per unit source radiance:
//
//   C_direct[s][p] = integral over source p of T(x_s, w) max(0, dot(w, n_s)) dw
//
// where T is the product of the straight transmittances (Material::straight_transmittance:
// Fresnel-weighted thin glass, openings) of the surfaces the shadow ray from the sensor
// passes, up to and including the first PORT it crosses; anything opaque before the port,
// or ANY surface after it (external obstructions; there is no external inter-reflection),
// makes T = 0, and so does a ray that leaves without crossing a port (photons enter only
// through ports). These are exactly the zero-event paths that the photon tracer does not
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
// Shadow rays start at the sensor moved ray_epsilon_m() along its normal (only directions
// with dot(w, n_s) > 0 are traced), so a sensor lying on a surface does not see that
// surface. A ray that would have to cross more than MaxShadowRayCrossings surfaces is
// treated as blocked (a guard against pathological stacks; real glazing has a few panes).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// Surfaces a shadow ray may pass before it counts as blocked (see the header comment).
constexpr int MaxShadowRayCrossings = 1000;

struct DirectOptions {
  int samples_per_source = 64;  ///< shadow rays per (sensor, source), >= 1; rounded up to a square
  std::uint64_t seed = 1;
};

/// Transmittance (RGB) from `origin` along `direction` (unit, toward the sky) to the sky
/// under the rule above. `materials[m]` is the model of scene material m (built by the
/// caller with Material::from_spec from SceneDescription::materials, same order). The ray
/// starts at `origin` with tmin = 0: offset it first if it lies on a surface.
/// Throws std::invalid_argument if `materials` has fewer entries than the description.
Vec3 sky_transmittance(const Scene& scene, const std::vector<Material>& materials,
                       const Vec3& origin, const Vec3& direction);

/// C_direct for every sensor (rows) and source (columns): result[s * sources.size() + p],
/// RGB, W/m^2 per unit radiance (W/m^2/sr). Parallel over sensors (oneTBB); every entry
/// depends only on (scene, materials, source p, sensor s, options), so the result is
/// identical for any thread count. Throws std::invalid_argument for samples_per_source < 1,
/// a sensor normal that is zero or not finite, or too few materials.
std::vector<Vec3> direct_coefficients(const Scene& scene, const std::vector<Material>& materials,
                                      const SourceSet& sources,
                                      const std::vector<SensorPoint>& sensors,
                                      const DirectOptions& options);

/// Direct irradiance at one sensor from a continuous sky radiance function
/// (direction toward the sky -> RGB radiance), integrated over the sources of `sources`
/// (the whole sphere when they are the bins of a basis, which partition it) with `samples`
/// stratified directions per source, seeded as sensor index 0 of direct_coefficients: with
/// the same seed and sample count it traces the very directions of sensor 0's
/// coefficients, so sum_p C[0][p] L_p and this integral differ only by the radiance
/// variation inside each source (used to check that the coefficients are linear).
Vec3 direct_irradiance(const Scene& scene, const std::vector<Material>& materials,
                       const SourceSet& sources, const SensorPoint& sensor,
                       const std::function<Vec3(const Vec3&)>& radiance, int samples,
                       std::uint64_t seed);

}  // namespace dayphoton::engine
