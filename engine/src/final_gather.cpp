// Final gather at point sensors: see final_gather.h for the estimator and its sources.
#include "dayphoton/engine/final_gather.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "bsdf_frame.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/density_estimate.h"
#include "dayphoton/engine/random.h"

namespace dayphoton::engine {
namespace {

constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;
/// Path weight (relative to a gather ray's start) below which Russian roulette is played.
constexpr double RouletteThreshold = 0.25;
/// Every path class: the direct photons at a gather hit are light reflected once toward x.
constexpr std::uint8_t AllPathClasses = path_class_bit(PathClass::Direct) | IndirectPathClasses;

double max_component(const Vec3& v) { return std::max({v.x, v.y, v.z}); }
Vec3 clamp_non_negative(const Vec3& v) { return {std::max(0.0, v.x), std::max(0.0, v.y), std::max(0.0, v.z)}; }

/// Add weight (.) sum_j K Phi_j of the disc of `bandwidth` photons at `at` on the side
/// `side` to per_source[photon source] (the contribution estimate, uniform kernel,
/// next-neighbour radius: density_estimate.h).
void add_contributions(const PhotonMap& map, const Vec3& at, const Vec3& side, std::size_t bandwidth,
                       const Vec3& weight, std::vector<NeighbourPhoton>& found, std::vector<Vec3>& per_source) {
  PhotonFilter filter;
  filter.path_classes = AllPathClasses;
  filter.check_normal = true;
  filter.normal = side;
  map.nearest(at, neighbours_needed(bandwidth, KernelRadius::NextNeighbour), std::numeric_limits<double>::infinity(),
              filter, found);
  const KernelDisc disc = kernel_disc(found, bandwidth, KernelRadius::NextNeighbour, std::numeric_limits<double>::infinity());
  // A disc of radius 0 (photons coinciding with the hit) has no density; it is skipped.
  if (disc.photon_count == 0 || !(disc.radius_m > 0)) return;
  const double k = 1.0 / (Pi * disc.radius_m * disc.radius_m);
  for (std::size_t j = 0; j < disc.photon_count; ++j) {
    const Photon& ph = map.photons()[found[j].index];
    if (ph.source >= per_source.size())
      throw std::invalid_argument("final gather: a photon of source " + std::to_string(ph.source) + " but " +
                                  std::to_string(per_source.size()) + " sources");
    per_source[ph.source] += mul(weight, ph.flux_rgb()) * k;
  }
}

struct SensorSums {
  std::vector<Vec3> caustic, global;
  std::vector<NeighbourPhoton> found;
};

/// One gather path from `origin` along `direction`, weight `weight` (1 / N per channel).
void gather_path(const Scene& scene, const std::vector<Material>& materials, const SourceSet& sources,
                 const PhotonMap& map, const GatherOptions& options, Vec3 origin, Vec3 direction,
                 Vec3 weight, Rng& rng, SensorSums& sums) {
  bool specular = false;     // a specular or glossy event since the sensor
  bool through_port = false;
  for (int event = 0;; ++event) {
    const std::optional<Hit> hit = scene.intersect(Ray{origin, direction, 0.0, std::numeric_limits<double>::infinity()});
    if (!hit) {
      // Unit radiance over the hemisphere: pi / N per ray, the 1 / N being in `weight`.
      if (through_port && specular) {
        const int p = sources.find(direction);
        if (p >= 0) sums.caustic[static_cast<std::size_t>(p)] += weight * Pi;
      }
      return;
    }
    // Outside, only an outdoor scatterer sends light on (its photons include those that
    // landed on it straight from the sources); anything else blocks the sky.
    if ((through_port && hit->scatterer < 0) || event > options.max_specular_events) return;
    const Material& material = materials[static_cast<std::size_t>(hit->material)];
    if (!hit->front_face && material.type() == MaterialType::Dielectric) {
      const Vec3 tpm = material.interior_transmittance_per_m();
      weight = mul(weight, {std::pow(tpm.x, hit->t), std::pow(tpm.y, hit->t), std::pow(tpm.z, hit->t)});
    }
    // The side the gather ray arrives on: light reflected toward the sensor leaves from there.
    const Vec3 side = hit->front_face ? hit->normal : hit->normal * -1.0;
    const Vec3 rho_d = diffuse_reflectance(material.spec());
    const Vec3 tau_d = diffuse_transmittance(material.spec());
    if (max_component(rho_d) > 0)
      add_contributions(map, hit->position, side, options.bandwidth, mul(weight, rho_d), sums.found, sums.global);
    if (max_component(tau_d) > 0)
      add_contributions(map, hit->position, side * -1.0, options.bandwidth, mul(weight, tau_d), sums.found, sums.global);
    // Specular, glossy and straight parts: follow one sampled event (the diffuse parts are in
    // the lookups above). Reciprocity lets the backward path use the forward sampling.
    const double u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const std::optional<ScatterSample> s = material.sample(direction, hit->normal, u0, u1, u2);
    if (!s) return;
    if (s->delta) {
      weight = mul(weight, s->weight);
      if (s->type != ScatterType::StraightTransmission) specular = true;
    } else {
      // Whichever component drew the direction, the glossy part of the BSDF there over the
      // whole mixture's pdf (a one-sample estimate of the glossy integral, unbiased); a
      // Lambertian surface leaves nothing beyond its lookup.
      const double pdf = material.pdf(direction, s->direction, hit->normal);
      if (!(pdf > 0)) return;
      const bool reflected = dot(s->direction, side) > 0;
      const Vec3 f_diffuse = (reflected ? rho_d : tau_d) * (1.0 / Pi);
      const Vec3 f = material.eval(direction, s->direction, hit->normal);
      const Vec3 glossy = clamp_non_negative(f - f_diffuse);
      if (!(max_component(glossy) > 1e-9 * max_component(f))) return;
      weight = mul(weight, glossy) * (std::fabs(dot(s->direction, hit->normal)) / pdf);
      specular = true;
    }
    if (hit->port >= 0 && dot(s->direction, side) < 0) through_port = true;
    // Russian roulette once the path weight falls below RouletteThreshold of its start
    // (1 / N): unbiased, and it ends the long tails of inter-reflecting specular surfaces
    // without touching a pane of glass or a mirror's first reflection.
    const double survive = std::min(1.0, max_component(weight) * options.rays_per_sensor / RouletteThreshold);
    if (!(survive > 0)) return;
    if (survive < 1) {
      if (rng.uniform() >= survive) return;
      weight = weight * (1.0 / survive);
    }
    origin = scene.offset_ray_origin(hit->position, hit->normal, s->direction);
    direction = s->direction;
  }
}

}  // namespace

GatheredCoefficients gather_photon_coefficients(const Scene& scene, const std::vector<Material>& materials,
                                                const SourceSet& sources, const PhotonMap& surface_photons,
                                                const std::vector<SensorPoint>& sensors,
                                                const GatherOptions& options) {
  if (options.rays_per_sensor < 1 || options.bandwidth < 1)
    throw std::invalid_argument("final gather: at least 1 ray per sensor and 1 photon per lookup are needed");
  if (materials.size() < scene.description().materials.size())
    throw std::invalid_argument("final gather: fewer material models than the scene has materials");
  int k = static_cast<int>(std::sqrt(static_cast<double>(options.rays_per_sensor)));
  while (k * k < options.rays_per_sensor) ++k;
  const std::size_t n_src = sources.size();
  GatheredCoefficients out;
  out.caustic.assign(sensors.size() * n_src, Vec3{});
  out.global.assign(sensors.size() * n_src, Vec3{});
  GatherOptions effective = options;
  effective.rays_per_sensor = k * k;
  const Vec3 ray_weight = Vec3{1, 1, 1} * (1.0 / (double(k) * k));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sensors.size()), [&](const tbb::blocked_range<std::size_t>& range) {
    SensorSums sums;
    for (std::size_t s = range.begin(); s != range.end(); ++s) {
      const double len = length(sensors[s].normal);
      if (!is_finite(sensors[s].normal) || !(len > 0.0) || !is_finite(sensors[s].position))
        throw std::invalid_argument("final gather: a sensor needs a finite position and a finite non-zero normal");
      const Vec3 normal = sensors[s].normal / len;
      const BsdfFrame frame(normal);
      const Vec3 origin = sensors[s].position + normal * scene.ray_epsilon_m();
      sums.caustic.assign(n_src, Vec3{});
      sums.global.assign(n_src, Vec3{});
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
          const std::uint64_t ray = static_cast<std::uint64_t>(i) * static_cast<std::uint64_t>(k) + static_cast<std::uint64_t>(j);
          Rng rng(options.seed, s, ray, RandomStream::Gather);
          // Malley's method: a stratified point on the unit disc (its square's strata mapped
          // by area), lifted to the hemisphere, is cosine-distributed.
          const double u1 = std::min((i + rng.uniform()) / k, OneMinusEpsilon);
          const double u2 = std::min((j + rng.uniform()) / k, OneMinusEpsilon);
          const double r = std::sqrt(u1), phi = 2.0 * Pi * u2;
          const Vec3 w = normalize(frame.to_world({r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))}));
          gather_path(scene, materials, sources, surface_photons, effective, origin, w, ray_weight, rng, sums);
        }
      std::copy(sums.caustic.begin(), sums.caustic.end(), out.caustic.begin() + static_cast<std::ptrdiff_t>(s * n_src));
      std::copy(sums.global.begin(), sums.global.end(), out.global.begin() + static_cast<std::ptrdiff_t>(s * n_src));
    }
  });
  return out;
}

}  // namespace dayphoton::engine
