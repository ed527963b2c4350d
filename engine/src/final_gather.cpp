// Final gather at point sensors: see final_gather.h for the estimator and its sources.
#include "dayphoton/engine/final_gather.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "bsdf_frame.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/density_estimate.h"
#include "dayphoton/engine/estimate_variance.h"
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

/// Sums and sums of squares over a sparse set of indices, reset as they are read.
class SparseSums {
 public:
  void resize(std::size_t n) {
    m_sum.assign(n, 0.0);
    m_square.assign(n, 0.0);
    m_marked.assign(n, 0);
    m_touched.clear();
  }
  void add(std::size_t i, double value) {
    if (!m_marked[i]) {
      m_marked[i] = 1;
      m_touched.push_back(static_cast<std::uint32_t>(i));
    }
    m_sum[i] += value;
    m_square[i] += value * value;
  }
  /// f(index, sum, sum of squares) for every index added to since the last drain, in the
  /// order first added (deterministic), then reset.
  template <class F>
  void drain(F f) {
    for (const std::uint32_t i : m_touched) {
      f(i, m_sum[i], m_square[i]);
      m_sum[i] = m_square[i] = 0.0;
      m_marked[i] = 0;
    }
    m_touched.clear();
  }

 private:
  std::vector<double> m_sum, m_square;
  std::vector<char> m_marked;
  std::vector<std::uint32_t> m_touched;
};

/// The variance bookkeeping of one sensor's gather (final_gather.h, "Variance"). Rays are
/// reported in stratum order (rows of k), each through add_photon / add_path and end_ray.
class GatherVariance {
 public:
  GatherVariance(const PhotonGroups& groups, std::size_t sources, int k, const std::vector<double>& weights)
      : m_groups(groups), m_k(k), m_weights(weights) {
    m_ray_source.resize(sources);
    m_run_source.resize(sources);
    m_rays.resize(sources);
    m_per_source.resize(sources);
    m_diagonal.resize(sources);
    m_ray_group.resize(groups.source_of.size());
    m_run_group.resize(groups.source_of.size());
    m_sensor_group.resize(groups.source_of.size());
  }
  /// A lookup term of luminance y from photon `photon` (tree order) of `source`.
  void add_photon(std::uint32_t photon, std::uint32_t source, double y) {
    m_ray_source.add(source, y);
    m_ray_group.add(m_groups.group_of[photon], y);
  }
  /// A specular path reaching `source` with luminance y (no photon: rays' variance only).
  void add_path(std::uint32_t source, double y) { m_ray_source.add(source, y); }
  void end_ray() {
    Ray& ray = m_window[m_in_row % 3];
    ray.total = 0;
    ray.sources.clear();
    ray.groups.clear();
    m_ray_source.drain([&](std::size_t p, double z, double) {
      const double weighted = m_weights.empty() ? z : m_weights[p] * z;
      ray.sources.push_back({static_cast<std::uint32_t>(p), weighted});
      ray.total += weighted;
    });
    m_ray_group.drain([&](std::size_t c, double z, double) {
      ray.groups.push_back({static_cast<std::uint32_t>(c), z});
      m_sensor_group.add(c, z);
      m_diagonal.add(m_groups.source_of[c], z * z);
    });
    ++m_in_row;
    // Rows of three or more strata: second differences of every run of three neighbours,
    // (z1 - 2 z2 + z3)^2 / 6, times k / (k - 2) for the row's sum (StratifiedVariance,
    // estimate_variance.h: a linear trend across the strata cancels).
    if (m_k >= 3 && m_in_row >= 3)
      add_run({&m_window[(m_in_row - 3) % 3], &m_window[(m_in_row - 2) % 3], &m_window[(m_in_row - 1) % 3]},
              {1.0, -2.0, 1.0}, double(m_k) / (double(m_k) - 2.0) / 6.0);
    if (m_in_row < m_k) return;
    // A row of two: the difference of the pair; a row of one: its square (no estimate is
    // possible, an upper bound about a mean of 0).
    if (m_k == 2) add_run({&m_window[0], &m_window[1], nullptr}, {1.0, -1.0, 0.0}, 1.0);
    if (m_k == 1) add_run({&m_window[0], nullptr, nullptr}, {1.0, 0.0, 0.0}, 1.0);
    m_in_row = 0;
  }
  /// The sensor's variance per source into `row` (sources entries) and the photons' part
  /// that more rays do not reduce into `fixed_row` (header comment, "Variance"), and reset.
  void end_sensor(double* row, double* fixed_row) {
    m_sensor_group.drain([&](std::size_t c, double sum, double) { m_per_source.add(m_groups.source_of[c], sum); });
    m_per_source.drain([&](std::size_t p, double sum, double square) {
      const double c = p < m_groups.groups_of_source.size() ? m_groups.groups_of_source[p] : 1.0;
      const double photons = c > 1 ? c / (c - 1) * (square - sum * sum / c) : square;
      row[p] += photons;
      fixed_row[p] = photons;
    });
    // Less the pairs of a group's terms on one ray: what is left are the pairs on two rays.
    m_diagonal.drain([&](std::size_t p, double sum, double) {
      const double c = p < m_groups.groups_of_source.size() ? m_groups.groups_of_source[p] : 1.0;
      fixed_row[p] -= c > 1 ? c / (c - 1) * sum : sum;
    });
    m_rays.drain([&](std::size_t p, double sum, double) { row[p] += sum; });
    m_in_row = 0;
  }

 private:
  struct Ray {
    double total = 0;  ///< the ray's value over all sources
    std::vector<std::pair<std::uint32_t, double>> sources, groups;
  };
  /// One run of neighbouring strata with coefficients `c` (0 for an absent ray) and factor
  /// `scale`: its variance scale (sum_i c_i z_i)^2 over the rays' values over all sources,
  /// shared among the sources by their part of the run's values (sum_i |c_i| z_ip: a ray is
  /// shared by the sources, as the direct component's port points are), less the photon
  /// noise those values carry, scale sum_groups (sum_i c_i S_ic)^2 (in the photon part
  /// already).
  void add_run(const std::array<const Ray*, 3>& run, const std::array<double, 3>& c, double scale) {
    double d = 0, values = 0;
    for (int i = 0; i < 3; ++i) {
      if (!run[i]) continue;
      d += c[i] * run[i]->total;
      values += std::fabs(c[i]) * run[i]->total;
      for (const auto& [p, z] : run[i]->sources) m_run_source.add(p, std::fabs(c[i]) * z);
      for (const auto& [g, z] : run[i]->groups) m_run_group.add(g, c[i] * z);
    }
    const double shared = scale * d * d;
    m_run_source.drain([&](std::size_t p, double sum, double) {
      const double w = m_weights.empty() ? 1.0 : m_weights[p];
      if (values > 0 && w > 0) m_rays.add(p, shared * sum / values / (w * w));
    });
    m_run_group.drain([&](std::size_t g, double sum, double) { m_rays.add(m_groups.source_of[g], -scale * sum * sum); });
  }

  const PhotonGroups& m_groups;
  int m_k;
  const std::vector<double>& m_weights;  ///< GatherOptions::variance_weights
  int m_in_row = 0;
  Ray m_window[3];  ///< the last three rays of the row, by index in the row mod 3
  SparseSums m_ray_source, m_run_source, m_rays, m_per_source, m_diagonal;
  SparseSums m_ray_group, m_run_group, m_sensor_group;
};

/// The continuous sky of a GatherOnSky, per source (final_gather.h, "The continuous sky").
struct SkyTerms {
  const SkyRatios* ratios = nullptr;
  std::vector<int> bin;                 ///< per source: its sky bin, -1 for a sun disc (ratio 1)
  std::vector<double> bin_luminance;    ///< per source: lum(L_p)
  double ratio(std::size_t source, const Vec3& toward_sky) const {
    return bin[source] < 0 ? 1.0 : ratios->ratio(static_cast<std::size_t>(bin[source]), toward_sky);
  }
};

struct SensorSums {
  std::vector<Vec3> caustic, global;
  std::vector<NeighbourPhoton> found;
  GatherVariance* variance = nullptr;
  /// With a GatherOnSky: per source, the ratio-weighted caustic + global (C'_p), and the
  /// variance of its sky-weighted terms.
  const SkyTerms* sky = nullptr;
  std::vector<Vec3> on_sky;
  GatherVariance* on_sky_variance = nullptr;
  /// With GatherOptions::sky_quadrants: per source and sky quadrant 0-2, the luminance of the
  /// terms whose light came through that quadrant of the source's bin (photon.h).
  bool shares = false;
  std::vector<double> quadrants;
};

/// Add weight (.) sum_j K Phi_j of the disc of `bandwidth` photons at `at` on the side
/// `side` to sums.global[photon source] (the contribution estimate, uniform kernel,
/// next-neighbour radius: density_estimate.h), and each term times the photon's sky ratio to
/// sums.on_sky (final_gather.h, "The continuous sky").
void add_contributions(const PhotonMap& map, const Vec3& at, const Vec3& side, std::size_t bandwidth,
                       const Vec3& weight, SensorSums& sums) {
  PhotonFilter filter;
  filter.path_classes = AllPathClasses;
  filter.check_normal = true;
  filter.normal = side;
  std::vector<NeighbourPhoton>& found = sums.found;
  map.nearest(at, neighbours_needed(bandwidth, KernelRadius::NextNeighbour), std::numeric_limits<double>::infinity(),
              filter, found);
  const KernelDisc disc = kernel_disc(found, bandwidth, KernelRadius::NextNeighbour, std::numeric_limits<double>::infinity());
  // A disc of radius 0 (photons coinciding with the hit) has no density; it is skipped.
  if (disc.photon_count == 0 || !(disc.radius_m > 0)) return;
  const double k = 1.0 / (Pi * disc.radius_m * disc.radius_m);
  for (std::size_t j = 0; j < disc.photon_count; ++j) {
    const Photon& ph = map.photons()[found[j].index];
    if (ph.source >= sums.global.size())
      throw std::invalid_argument("final gather: a photon of source " + std::to_string(ph.source) + " but " +
                                  std::to_string(sums.global.size()) + " sources");
    const Vec3 term = mul(weight, ph.flux_rgb()) * k;
    sums.global[ph.source] += term;
    if (sums.variance) sums.variance->add_photon(found[j].index, ph.source, luminance_of(term));
    if (sums.shares && ph.sky_quadrant < StoredQuadrants)
      sums.quadrants[std::size_t(ph.source) * StoredQuadrants + ph.sky_quadrant] += luminance_of(term);
    if (sums.sky) {
      const Vec3 weighted = term * ph.sky_ratio();
      sums.on_sky[ph.source] += weighted;
      if (sums.on_sky_variance)
        sums.on_sky_variance->add_photon(found[j].index, ph.source,
                                         luminance_of(weighted) * sums.sky->bin_luminance[ph.source]);
    }
  }
}

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
        if (p >= 0) {
          sums.caustic[static_cast<std::size_t>(p)] += weight * Pi;
          if (sums.variance) sums.variance->add_path(static_cast<std::uint32_t>(p), luminance_of(weight * Pi));
          // The quadrant of its bin the path leaves through (the ground's and a disc's: none).
          const DistantSource& left_by = sources[static_cast<std::size_t>(p)];
          if (sums.shares && left_by.kind == SourceKind::SkyBin && left_by.bin > 0) {
            const int q = sources.basis().quadrant(left_by.bin, direction);
            if (q < int(StoredQuadrants))
              sums.quadrants[static_cast<std::size_t>(p) * StoredQuadrants + std::size_t(q)] += luminance_of(weight * Pi);
          }
          if (sums.sky) {
            // The sky's own radiance in the direction the path leaves by (its ratio to L_p).
            const std::size_t q = static_cast<std::size_t>(p);
            const Vec3 weighted = weight * (Pi * sums.sky->ratio(q, direction));
            sums.on_sky[q] += weighted;
            if (sums.on_sky_variance)
              sums.on_sky_variance->add_path(static_cast<std::uint32_t>(p),
                                             luminance_of(weighted) * sums.sky->bin_luminance[q]);
          }
        }
      }
      return;
    }
    // Outside, only an outdoor scatterer sends light on (its photons include those that
    // landed on it straight from the sources); anything else blocks the sky.
    if ((through_port && hit->scatterer < 0) || event > options.max_specular_events) return;
    const Material& material = materials[static_cast<std::size_t>(hit->material)];
    if (!hit->front_face && material.absorbs_inside()) {
      const Vec3 tpm = material.interior_transmittance_per_m();
      weight = mul(weight, {std::pow(tpm.x, hit->t), std::pow(tpm.y, hit->t), std::pow(tpm.z, hit->t)});
    }
    // The side the gather ray arrives on: light reflected toward the sensor leaves from there.
    const Vec3 side = hit->front_face ? hit->normal : hit->normal * -1.0;
    const Vec3 rho_d = material.diffuse_reflectance();
    const Vec3 tau_d = material.diffuse_transmittance();
    if (max_component(rho_d) > 0) add_contributions(map, hit->position, side, options.bandwidth, mul(weight, rho_d), sums);
    if (max_component(tau_d) > 0)
      add_contributions(map, hit->position, side * -1.0, options.bandwidth, mul(weight, tau_d), sums);
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

PhotonGroups PhotonGroups::consecutive(const std::vector<Photon>& photons, std::size_t sources,
                                       std::size_t group_size) {
  if (group_size == 0) throw std::invalid_argument("photon groups: a group needs at least one photon");
  PhotonGroups g;
  g.groups_of_source.assign(sources, 0);
  g.group_of.resize(photons.size());
  std::size_t in_group = 0;
  for (std::size_t i = 0; i < photons.size(); ++i) {
    const std::uint32_t source = photons[i].source;
    if (source >= sources)
      throw std::invalid_argument("photon groups: a photon of source " + std::to_string(source) + " but " +
                                  std::to_string(sources) + " sources");
    if (g.source_of.empty() || g.source_of.back() != source || in_group == group_size) {
      g.source_of.push_back(source);
      ++g.groups_of_source[source];
      in_group = 0;
    }
    ++in_group;
    g.group_of[i] = static_cast<std::uint32_t>(g.source_of.size() - 1);
  }
  return g;
}

void PhotonGroups::to_tree_order(const std::vector<std::uint32_t>& tree_to_input) {
  if (tree_to_input.size() != group_of.size())
    throw std::invalid_argument("photon groups: the permutation does not match the photons");
  std::vector<std::uint32_t> in_tree(group_of.size());
  for (std::size_t t = 0; t < tree_to_input.size(); ++t) in_tree[t] = group_of[tree_to_input[t]];
  group_of = std::move(in_tree);
}

namespace {

/// The gather at sensors[which[r]] into row r.
GatheredCoefficients gather_rows(const Scene& scene, const std::vector<Material>& materials, const SourceSet& sources,
                                 const PhotonMap& surface_photons, const std::vector<SensorPoint>& sensors,
                                 const GatherOptions& options, const PhotonGroups* groups,
                                 const std::vector<std::size_t>& which, const GatherOnSky* on_sky) {
  if (options.rays_per_sensor < 1 || options.bandwidth < 1)
    throw std::invalid_argument("final gather: at least 1 ray per sensor and 1 photon per lookup are needed");
  if (materials.size() < scene.description().materials.size())
    throw std::invalid_argument("final gather: fewer material models than the scene has materials");
  int k = static_cast<int>(std::sqrt(static_cast<double>(options.rays_per_sensor)));
  while (k * k < options.rays_per_sensor) ++k;
  const std::size_t n_src = sources.size();
  GatheredCoefficients out;
  out.caustic.assign(which.size() * n_src, Vec3{});
  out.global.assign(which.size() * n_src, Vec3{});
  const bool shares = options.sky_quadrants && sources.has_basis();
  if (shares) out.quadrants.assign(which.size() * n_src * StoredQuadrants, 0.0f);
  GatherOptions effective = options;
  effective.rays_per_sensor = k * k;
  const Vec3 ray_weight = Vec3{1, 1, 1} * (1.0 / (double(k) * k));
  if (!options.variance_weights.empty()) {
    if (options.variance_weights.size() != n_src)
      throw std::invalid_argument("final gather: " + std::to_string(options.variance_weights.size()) +
                                  " variance weights for " + std::to_string(n_src) + " sources");
    for (const double w : options.variance_weights)
      if (!(w >= 0) || !std::isfinite(w))
        throw std::invalid_argument("final gather: a variance weight is negative or not finite");
  }
  if (groups) {
    if (groups->group_of.size() != surface_photons.size())
      throw std::invalid_argument("final gather: the photon groups are not those of the map");
    out.variance.assign(which.size() * n_src, 0.0);
    out.fixed_photon_variance.assign(which.size() * n_src, 0.0);
  }
  SkyTerms sky;
  if (on_sky) {
    if (on_sky->bin_radiance_rgb.size() != n_src)
      throw std::invalid_argument("final gather: " + std::to_string(on_sky->bin_radiance_rgb.size()) +
                                  " bin radiances for " + std::to_string(n_src) + " sources");
    sky.ratios = &on_sky->ratios;
    for (std::size_t p = 0; p < n_src; ++p) {
      const DistantSource& source = sources[p];
      const int bin = source.kind == SourceKind::SkyBin ? std::max(0, source.bin) : -1;
      if (bin >= 0 && std::size_t(bin) >= on_sky->ratios.bins())
        throw std::invalid_argument("final gather: sky ratios of " + std::to_string(on_sky->ratios.bins()) +
                                    " bins for sky bin " + std::to_string(bin));
      sky.bin.push_back(bin);
      sky.bin_luminance.push_back(luminance_of(on_sky->bin_radiance_rgb[p]));
    }
    out.on_sky.assign(which.size(), Vec3{});
    if (groups) out.on_sky_variance.assign(which.size(), 0.0);
  }
  // Scratch of the variance per thread (sized by the groups, reset after each sensor, so
  // which thread runs a sensor changes nothing): the basis's, and the continuous sky's with
  // its terms already sky-weighted (no weights).
  const std::vector<double> no_weights;
  struct Scratch {
    std::unique_ptr<GatherVariance> basis, on_sky;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, which.size()), [&](const tbb::blocked_range<std::size_t>& range) {
    SensorSums sums;
    if (on_sky) sums.sky = &sky;
    sums.shares = shares;
    std::vector<double> sky_row, sky_fixed;
    if (groups) {
      Scratch& v = scratch.local();
      if (!v.basis) v.basis = std::make_unique<GatherVariance>(*groups, n_src, k, options.variance_weights);
      sums.variance = v.basis.get();
      if (on_sky) {
        if (!v.on_sky) v.on_sky = std::make_unique<GatherVariance>(*groups, n_src, k, no_weights);
        sums.on_sky_variance = v.on_sky.get();
      }
    }
    for (std::size_t at_row = range.begin(); at_row != range.end(); ++at_row) {
      const std::size_t s = which[at_row];
      if (s >= sensors.size()) throw std::invalid_argument("final gather: a sensor index is not within the grid");
      const double len = length(sensors[s].normal);
      if (!is_finite(sensors[s].normal) || !(len > 0.0) || !is_finite(sensors[s].position))
        throw std::invalid_argument("final gather: a sensor needs a finite position and a finite non-zero normal");
      const Vec3 normal = sensors[s].normal / len;
      const BsdfFrame frame(normal);
      const Vec3 origin = sensors[s].position + normal * scene.ray_epsilon_m();
      sums.caustic.assign(n_src, Vec3{});
      sums.global.assign(n_src, Vec3{});
      if (on_sky) sums.on_sky.assign(n_src, Vec3{});
      if (shares) sums.quadrants.assign(n_src * StoredQuadrants, 0.0);
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
          if (sums.variance) sums.variance->end_ray();
          if (sums.on_sky_variance) sums.on_sky_variance->end_ray();
        }
      if (sums.variance) {
        double* row = out.variance.data() + at_row * n_src;
        double* fixed = out.fixed_photon_variance.data() + at_row * n_src;
        sums.variance->end_sensor(row, fixed);
        for (std::size_t p = 0; p < n_src; ++p) {
          row[p] = std::max(0.0, row[p]);
          fixed[p] = std::clamp(fixed[p], 0.0, row[p]);
        }
      }
      if (on_sky) {
        // E = sum_p L_p C'_p; its variance the sum of the sources' (their terms sky-weighted).
        Vec3 e{0, 0, 0};
        for (std::size_t p = 0; p < n_src; ++p) e += mul(sums.on_sky[p], on_sky->bin_radiance_rgb[p]);
        out.on_sky[at_row] = e;
        if (sums.on_sky_variance) {
          sky_row.assign(n_src, 0.0);
          sky_fixed.assign(n_src, 0.0);
          sums.on_sky_variance->end_sensor(sky_row.data(), sky_fixed.data());
          double v = 0;
          for (std::size_t p = 0; p < n_src; ++p) v += std::max(0.0, sky_row[p]);
          out.on_sky_variance[at_row] = v;
        }
      }
      if (shares)
        for (std::size_t x = 0; x < n_src * StoredQuadrants; ++x)
          out.quadrants[at_row * n_src * StoredQuadrants + x] = float(sums.quadrants[x]);
      const auto at = static_cast<std::ptrdiff_t>(at_row * n_src);
      std::copy(sums.caustic.begin(), sums.caustic.end(), out.caustic.begin() + at);
      std::copy(sums.global.begin(), sums.global.end(), out.global.begin() + at);
    }
  });
  return out;
}

}  // namespace

GatheredCoefficients gather_photon_coefficients(const Scene& scene, const std::vector<Material>& materials,
                                                const SourceSet& sources, const PhotonMap& surface_photons,
                                                const std::vector<SensorPoint>& sensors,
                                                const GatherOptions& options, const PhotonGroups* groups,
                                                SensorRange rows, const GatherOnSky* on_sky) {
  rows = rows.within(sensors.size());
  std::vector<std::size_t> which(rows.size());
  for (std::size_t r = 0; r < which.size(); ++r) which[r] = rows.begin + r;
  return gather_rows(scene, materials, sources, surface_photons, sensors, options, groups, which, on_sky);
}

GatheredCoefficients gather_photon_coefficients_at(const Scene& scene, const std::vector<Material>& materials,
                                                const SourceSet& sources, const PhotonMap& surface_photons,
                                                const std::vector<SensorPoint>& sensors,
                                                const GatherOptions& options, const PhotonGroups* groups,
                                                const std::vector<std::size_t>& which, const GatherOnSky* on_sky) {
  return gather_rows(scene, materials, sources, surface_photons, sensors, options, groups, which, on_sky);
}

}  // namespace dayphoton::engine
