// Fixed-bandwidth density estimates and the contribution estimate (seeds/000 section 3.1.3,
// section 6.2 for the averaged radius; seeds/001 eq. 18). Rules for the kernel disc, the
// maximum search radius and the degenerate cases: see density_estimate.h.
#include "dayphoton/engine/density_estimate.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/engine/engine_error.h"
#include "dayphoton/engine/estimate_variance.h"

namespace dayphoton::engine {
namespace {

void check_options(const DensityEstimateOptions& options) {
  if (options.bandwidth == 0)
    throw std::invalid_argument("density estimate: the bandwidth must be at least 1 photon");
  if (!(options.max_radius_m > 0) || !std::isfinite(options.max_radius_m))
    throw std::invalid_argument("density estimate: the maximum search radius must be positive and finite");
}

/// Photons to gather: the (N+1)-th defines the averaged radius.
std::size_t lookup_count(const DensityEstimateOptions& options) {
  return neighbours_needed(options.bandwidth, options.radius);
}

}  // namespace

Vec3 accumulate_disc(const PhotonMap& map, const std::vector<NeighbourPhoton>& sorted,
                     const KernelDisc& disc, KernelType kernel, std::vector<Vec3>* per_source,
                     double* luminance_variance, std::vector<double>* per_source_variance, PhotonFlux flux) {
  if (disc.photon_count == 0) return Vec3{};
  const auto& photons = map.photons();
  if (!(disc.radius_m > 0)) {
    const Vec3 at = photons[sorted[0].index].position_m();
    throw EngineError("density estimate at (" + std::to_string(at.x) + ", " +
                      std::to_string(at.y) + ", " + std::to_string(at.z) +
                      "): the photons that define the kernel radius all lie on the query "
                      "point, so the density is not finite");
  }
  if (per_source) {
    for (std::size_t j = 0; j < disc.photon_count; ++j) {
      const std::uint32_t source = photons[sorted[j].index].source;
      if (source >= per_source->size())
        throw std::out_of_range("contribution estimate: a photon of source " +
                                std::to_string(source) + " but only " +
                                std::to_string(per_source->size()) + " source slots");
    }
  }
  // The uniform kernel has one weight for all photons: skip the square roots.
  const bool uniform = kernel == KernelType::Uniform;
  const double uniform_weight = kernel_weight(KernelType::Uniform, 0.0, disc.radius_m);
  Vec3 sum{};
  for (std::size_t j = 0; j < disc.photon_count; ++j) {
    const Photon& photon = photons[sorted[j].index];
    const double weight =
        uniform ? uniform_weight
                : kernel_weight(kernel, std::sqrt(sorted[j].distance_squared_m2), disc.radius_m);
    const Vec3 term = flux_of(photon, flux) * weight;
    sum += term;
    if (per_source) (*per_source)[photon.source] += term;
    if (luminance_variance || per_source_variance) {
      // The estimate is a sum over independent photons: its variance is the sum of the
      // squared terms (estimate_variance.h).
      const double y = luminance_of(term);
      if (luminance_variance) *luminance_variance += y * y;
      if (per_source_variance && photon.source < per_source_variance->size())
        (*per_source_variance)[photon.source] += y * y;
    }
  }
  return sum;
}

KernelDisc kernel_disc(const std::vector<NeighbourPhoton>& sorted, std::size_t bandwidth,
                       KernelRadius radius, double max_radius_m) {
  KernelDisc disc;
  const std::size_t needed = neighbours_needed(bandwidth, radius);
  if (bandwidth == 0 || sorted.size() < needed) {
    // Short lookup: the radius-defining photon lies beyond the maximum search radius.
    disc.radius_m = max_radius_m;
    disc.photon_count = sorted.size();
    return disc;
  }
  const double d_n = std::sqrt(sorted[bandwidth - 1].distance_squared_m2);
  switch (radius) {
    case KernelRadius::Plain: disc.radius_m = d_n; break;
    case KernelRadius::Averaged:
      disc.radius_m = 0.5 * (d_n + std::sqrt(sorted[bandwidth].distance_squared_m2));
      break;
    case KernelRadius::NextNeighbour:
      disc.radius_m = std::sqrt(sorted[bandwidth].distance_squared_m2);
      break;
  }
  disc.photon_count = bandwidth;
  return disc;
}

DensityEstimate estimate_irradiance(const PhotonMap& map, const Vec3& point,
                                    const PhotonFilter& filter,
                                    const DensityEstimateOptions& options) {
  check_options(options);
  std::vector<NeighbourPhoton> neighbours;
  map.nearest(point, lookup_count(options), options.max_radius_m, filter, neighbours);
  const KernelDisc disc =
      kernel_disc(neighbours, options.bandwidth, options.radius, options.max_radius_m);
  DensityEstimate estimate;
  estimate.radius_m = disc.radius_m;
  estimate.photon_count = disc.photon_count;
  estimate.irradiance =
      accumulate_disc(map, neighbours, disc, options.kernel, nullptr, &estimate.luminance_variance, nullptr, options.flux);
  return estimate;
}

DensityEstimate estimate_contributions(const PhotonMap& map, const Vec3& point,
                                       const PhotonFilter& filter,
                                       const DensityEstimateOptions& options,
                                       std::vector<Vec3>& per_source,
                                       std::vector<double>* per_source_variance) {
  check_options(options);
  PhotonFilter any_source = filter;
  any_source.source = PhotonFilter::AnySource;
  std::vector<NeighbourPhoton> neighbours;
  map.nearest(point, lookup_count(options), options.max_radius_m, any_source, neighbours);
  const KernelDisc disc =
      kernel_disc(neighbours, options.bandwidth, options.radius, options.max_radius_m);
  DensityEstimate estimate;
  estimate.radius_m = disc.radius_m;
  estimate.photon_count = disc.photon_count;
  estimate.irradiance = accumulate_disc(map, neighbours, disc, options.kernel, &per_source,
                                       &estimate.luminance_variance, per_source_variance, options.flux);
  return estimate;
}

}  // namespace dayphoton::engine
