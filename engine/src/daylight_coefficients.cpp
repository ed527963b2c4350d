// Daylight coefficients: see daylight_coefficients.h.
#include "dayphoton/engine/daylight_coefficients.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/local_quadratic_fit.h"
#include "dayphoton/engine/photon_part_on_sky.h"
#include "dayphoton/engine/plane_cuts.h"
#include "dayphoton/engine/plane_visibility.h"

namespace dayphoton::engine {
namespace {

/// Fewest photons in a disc for the quadratic curvature correction. On a whole disc the quadratic's
/// relative standard deviation is 2 / sqrt(n) (4 times the plane's variance), and the clamp
/// of a normal N(1, s^2) at 0 raises its mean by s phi(1/s) - Phi(-1/s): 2.5 % at the sparse
/// sources' 8 photons (MinimumSourceBandwidth), 0.02 % at 32.
constexpr std::size_t QuadraticEverywhereMinimumPhotons = 32;

std::vector<PhotonMap> split_by_source(const std::vector<Photon>& photons, std::size_t sources) {
  std::vector<std::vector<Photon>> parts(sources);
  for (const Photon& p : photons)
    if (p.source < sources) parts[p.source].push_back(p);
  std::vector<PhotonMap> maps(sources);
  tbb::parallel_for(std::size_t(0), sources,
                    [&](std::size_t s) { maps[s] = PhotonMap(std::move(parts[s])); });
  return maps;
}

// pi r^2 / (area of the kernel disc inside the outline, or of the part the centre sees):
// 1 away from walls.
double boundary_factor(const ReceiverPlane* plane, const PlaneVisibility* visibility, const Vec3& at,
                       double radius_m) {
  if (!plane || radius_m <= 0) return 1.0;
  const double inside =
      visibility ? visibility->area_m2(radius_m) : plane->disc_area_inside_m2(at.x, at.y, radius_m);
  const double full = Pi * radius_m * radius_m;
  return inside > 1e-12 * full ? full / inside : 1.0;
}

BiasCompensationOptions bias_options(const CoefficientOptions& options,
                                     const DensityEstimateOptions& density, std::size_t index) {
  BiasCompensationOptions b;
  b.n_min = density.bandwidth;
  b.n_max = density.bandwidth * std::max<std::size_t>(1, options.bias_compensation_max_factor);
  b.max_radius_m = density.max_radius_m;
  b.kernel = density.kernel;
  b.rng_seed = options.seed;
  b.rng_index = index;
  b.flux = density.flux;
  return b;
}

/// Local-linear density at the disc's centre from the photon sums S0 = sum Phi and
/// S1 = sum Phi (q - x) (per channel): the first unknown of the 3 x 3 moment system, by
/// Cramer's rule. Falls back to S0 / A when the system is degenerate. A channel whose fitted
/// plane is negative at the centre is set to 0: a steep fitted gradient over a wide disc (few
/// photons at the far side of a room, e.g. behind closed blinds) extrapolates below zero,
/// and the negative values added up over sources into negative hourly illuminance. There the
/// true value is small against the disc's (which is why the fit went negative), so 0 is off
/// by at most that small value, while the plain average S0 / A can be many times too high.
Vec3 local_linear_density(const AreaMoments& m, const Vec3& s0, const Vec3& s1x, const Vec3& s1y) {
  const double a11 = m.area, a12 = m.mx, a13 = m.my;
  const double a22 = m.mxx, a23 = m.mxy, a33 = m.myy;
  const double det = a11 * (a22 * a33 - a23 * a23) - a12 * (a12 * a33 - a23 * a13) +
                     a13 * (a12 * a23 - a22 * a13);
  const double scale = a11 * a22 * a33;
  if (!(m.area > 0)) return {0, 0, 0};
  if (!(std::fabs(det) > 1e-9 * std::fabs(scale))) return s0 * (1.0 / m.area);
  // Replace the first column by the right-hand side.
  auto solve = [&](double b1, double b2, double b3) {
    const double d1 = b1 * (a22 * a33 - a23 * a23) - a12 * (b2 * a33 - a23 * b3) +
                      a13 * (b2 * a23 - a22 * b3);
    return d1 / det;
  };
  const Vec3 fitted{solve(s0.x, s1x.x, s1y.x), solve(s0.y, s1x.y, s1y.y), solve(s0.z, s1x.z, s1y.z)};
  return {std::max(0.0, fitted.x), std::max(0.0, fitted.y), std::max(0.0, fitted.z)};
}

}  // namespace

RadianceMatrix DaylightCoefficients::to_matrix() const {
  RadianceMatrix m(sensors, sources, 3);
  for (std::size_t s = 0; s < sensors; ++s)
    for (std::size_t p = 0; p < sources; ++p) {
      const Vec3 c = total(s, p);
      m.at(s, p, 0) = static_cast<float>(c.x);
      m.at(s, p, 1) = static_cast<float>(c.y);
      m.at(s, p, 2) = static_cast<float>(c.z);
    }
  return m;
}

namespace {

/// bandwidth x n / typical, at least min(bandwidth, MinimumSourceBandwidth) (the header's
/// sparse-source rule); `bandwidth` when there is no typical count.
std::size_t scaled_bandwidth(std::size_t bandwidth, std::size_t n, std::size_t typical) {
  if (typical == 0 || n == typical) return bandwidth;
  const std::size_t floor = std::min(bandwidth, MinimumSourceBandwidth);
  const double scaled = std::round(double(bandwidth) * double(n) / double(typical));
  return std::max(floor, static_cast<std::size_t>(scaled));
}

}  // namespace

std::size_t GridPhotons::bandwidth_of(std::size_t source, std::size_t bandwidth) const {
  return scaled_bandwidth(bandwidth, m_by_source[source].size(), m_typical_count);
}

std::size_t GridPhotons::bandwidth_of(std::size_t source, std::size_t bandwidth, PathClass path_class) const {
  const int c = path_class == PathClass::Caustic ? 0 : 1;
  return scaled_bandwidth(bandwidth, m_class_counts[c][source], m_typical_class_count[c]);
}

double GridPhotons::max_radius_m(std::size_t bandwidth) const {
  if (!m_plane || m_typical_count == 0) return std::numeric_limits<double>::infinity();
  const double area_m2 = m_plane->outline_area_m2();
  if (!(area_m2 > 0)) return std::numeric_limits<double>::infinity();
  return MaxRadiusFactor * std::sqrt(double(bandwidth) * area_m2 / (Pi * double(m_typical_count)));
}

void GridPhotons::count_classes() {
  for (int c = 0; c < 2; ++c) {
    m_class_counts[c].assign(m_by_source.size(), 0);
    std::vector<std::size_t> nonzero;
    for (std::size_t p = 0; p < m_by_source.size(); ++p) {
      for (const Photon& ph : m_by_source[p].photons())
        if ((ph.path_class == PathClass::Caustic) == (c == 0) && ph.path_class != PathClass::Direct)
          ++m_class_counts[c][p];
      if (m_class_counts[c][p] > 0) nonzero.push_back(m_class_counts[c][p]);
    }
    if (nonzero.empty()) continue;
    std::nth_element(nonzero.begin(), nonzero.begin() + nonzero.size() / 2, nonzero.end());
    m_typical_class_count[c] = nonzero[nonzero.size() / 2];
  }
}

void GridPhotons::set_source_scale(const std::vector<double>& scale) {
  auto median_at_reference = [&scale](auto count_of, std::size_t n) -> std::size_t {
    std::vector<double> counts;
    for (std::size_t p = 0; p < n; ++p) {
      const double c = double(count_of(p));
      if (c > 0) counts.push_back(p < scale.size() && scale[p] > 0 ? c / scale[p] : c);
    }
    if (counts.empty()) return 0;
    std::nth_element(counts.begin(), counts.begin() + counts.size() / 2, counts.end());
    return static_cast<std::size_t>(std::max(1.0, std::round(counts[counts.size() / 2])));
  };
  m_typical_count = median_at_reference([this](std::size_t p) { return m_by_source[p].size(); }, m_by_source.size());
  for (int c = 0; c < 2; ++c)
    m_typical_class_count[c] =
        median_at_reference([this, c](std::size_t p) { return m_class_counts[c][p]; }, m_class_counts[c].size());
}

std::size_t GridPhotons::median_count(const std::vector<PhotonMap>& maps) {
  std::vector<std::size_t> counts;
  for (const PhotonMap& m : maps)
    if (!m.empty()) counts.push_back(m.size());
  if (counts.empty()) return 0;
  std::nth_element(counts.begin(), counts.begin() + counts.size() / 2, counts.end());
  return counts[counts.size() / 2];
}

GridPhotons GridPhotons::for_plane(const ReceiverPlane& plane, std::vector<Photon> plane_photons,
                                   std::size_t source_count) {
  GridPhotons g;
  g.m_plane = plane;
  g.m_source_count = source_count;
  g.m_by_source = split_by_source(plane_photons, source_count);
  g.m_typical_count = median_count(g.m_by_source);
  g.count_classes();
  g.m_all->photons = std::move(plane_photons);
  return g;
}

GridPhotons GridPhotons::for_surfaces(std::vector<Photon> surface_photons,
                                      std::size_t source_count) {
  GridPhotons g;
  g.m_source_count = source_count;
  surface_photons.erase(std::remove_if(surface_photons.begin(), surface_photons.end(),
                                       [](const Photon& p) { return p.path_class == PathClass::Direct; }),
                        surface_photons.end());
  g.m_by_source = split_by_source(surface_photons, source_count);
  g.m_typical_count = median_count(g.m_by_source);
  g.count_classes();
  g.m_all->photons = std::move(surface_photons);
  return g;
}

GridPhotons GridPhotons::for_gather(std::vector<Photon> surface_photons, std::size_t source_count) {
  GridPhotons g;
  g.m_gather = true;
  g.m_source_count = source_count;
  // Groups of consecutive photons (tracing order) for the variance, before the build reorders.
  g.m_groups = PhotonGroups::consecutive(surface_photons, source_count);
  std::vector<std::uint32_t> tree_to_input;
  std::call_once(g.m_all->built,
                 [&] { g.m_all->map = PhotonMap(std::move(surface_photons), tree_to_input); });
  g.m_groups.to_tree_order(tree_to_input);
  return g;
}

void GridPhotons::set_near_cut_gather(std::shared_ptr<const GridPhotons> gather) {
  if (!m_plane) throw std::invalid_argument("near-cut gather photons: only a receiver plane's sensors are gathered");
  if (gather && (!gather->gather() || gather->source_count() != m_source_count))
    throw std::invalid_argument("near-cut gather photons: gather photons of " + std::to_string(m_source_count) +
                                " sources are needed");
  m_near_cut_gather = std::move(gather);
}

const PhotonMap& GridPhotons::all() const {
  // Isolated: the build's own parallel tasks must not pick up an outer task (an estimate
  // at another sensor) that would wait for this very call_once.
  std::call_once(m_all->built, [this] {
    tbb::this_task_arena::isolate([this] {
      m_all->map = PhotonMap(std::move(m_all->photons));
      m_all->photons = {};
    });
  });
  return m_all->map;
}

namespace {

struct ClassEstimates {
  Vec3 caustic{0, 0, 0}, global{0, 0, 0};
  double variance = 0;  ///< of caustic + global's luminance (estimate_variance.h)
};

/// The luminances of caustic + global of the same estimate with each flux times the indicator
/// of its sky quadrant 0, 1, 2 (the photon part's sub-patch shares, photon.h).
using QuadrantShares = std::array<double, StoredQuadrants>;

/// The variance of the local-linear estimate at the disc's centre: the estimate is
/// sum_j (c1 + c2 dx_j + c3 dy_j) Phi_j, c the first row of the inverse moment matrix, so its
/// variance is sum_j (c . (1, dx_j, dy_j))^2 y_j^2 = c^T Q c with Q the sums of
/// y^2 (1, dx, dy)(1, dx, dy)^T (`q`: 1, dx, dy, dx dx, dx dy, dy dy). The clamp at 0 is left
/// out (it only removes variance).
double local_linear_variance(const AreaMoments& m, const double q[6]) {
  const double a11 = m.area, a12 = m.mx, a13 = m.my;
  const double a22 = m.mxx, a23 = m.mxy, a33 = m.myy;
  if (!(m.area > 0)) return 0.0;
  const double det = a11 * (a22 * a33 - a23 * a23) - a12 * (a12 * a33 - a23 * a13) +
                     a13 * (a12 * a23 - a22 * a13);
  const double scale = a11 * a22 * a33;
  if (!(std::fabs(det) > 1e-9 * std::fabs(scale))) return q[0] / (m.area * m.area);
  const double c1 = (a22 * a33 - a23 * a23) / det;
  const double c2 = (a13 * a23 - a12 * a33) / det;
  const double c3 = (a12 * a23 - a13 * a22) / det;
  return c1 * c1 * q[0] + 2 * c1 * c2 * q[1] + 2 * c1 * c3 * q[2] + c2 * c2 * q[3] + 2 * c2 * c3 * q[4] +
         c3 * c3 * q[5];
}

/// The local-quadratic estimate over the disc's photons (local_quadratic_fit.h): per class
/// sum_j w_j Phi_j with w_j = kernel.weight((x_j - at) / r) / r^2, and its variance
/// sum_j w_j^2 y_j^2. A channel whose total (caustic + global) is negative (a quadratic
/// extrapolated to the centre where the light is small against its noise) is set to 0 in both
/// classes; a class alone is not clamped: its equivalent kernel's negative lobes make a class
/// with few photons in the disc (caustic photons among the ground's) negative about as often
/// as not, and clamping it would bias it upwards. Every consumer reads the total
/// (DaylightCoefficients::total). The variance leaves the clamp out (it only removes variance).
ClassEstimates local_quadratic_estimate(const PhotonMap& map, const Vec3& at, const std::vector<NeighbourPhoton>& found,
                                        const KernelDisc& disc, const LocalQuadraticKernel& kernel,
                                        PhotonFlux photon_flux) {
  const double inv_r = 1.0 / disc.radius_m, inv_r2 = inv_r * inv_r;
  Vec3 sum[2] = {Vec3{0, 0, 0}, Vec3{0, 0, 0}};
  double variance = 0;
  for (std::size_t j = 0; j < disc.photon_count; ++j) {
    const Photon& ph = map.photons()[found[j].index];
    const Vec3 flux = flux_of(ph, photon_flux);
    const double w = kernel.weight((double(ph.position[0]) - at.x) * inv_r, (double(ph.position[1]) - at.y) * inv_r);
    sum[ph.path_class == PathClass::Caustic ? 0 : 1] += flux * w;
    const double wy = w * luminance_of(flux);
    variance += wy * wy;
  }
  ClassEstimates out;
  out.caustic = sum[0] * inv_r2;
  out.global = sum[1] * inv_r2;
  for (int k = 0; k < 3; ++k)
    if (out.caustic[k] + out.global[k] < 0) {
      out.caustic[k] = 0;
      out.global[k] = 0;
    }
  out.variance = variance * inv_r2 * inv_r2;
  return out;
}

/// The search hint of one source's lookups over consecutive sensors: the k-th distance
/// found at the previous sensor. By the triangle inequality that distance plus the step
/// between the two sensors holds the k photons found there, so it is a radius holding k
/// photons at this sensor: PhotonMap::nearest's hint, which never changes the photons found,
/// only how much of the tree the search visits.
class LookupHint {
 public:
  /// The hint at `at` (NaN: none). The relative margin covers the rounding of the
  /// distances; a hint too small would cost a second search, never a different result.
  /// After a short lookup (fewer than k within the maximum radius) the hint is the maximum
  /// radius itself: the next sensor's search, likely short too, collects every photon within
  /// it without a heap (PhotonMap::nearest).
  double radius_m(const Vec3& at, double max_radius_m) const {
    if (m_short) return max_radius_m;
    return (m_kth_m + length(at - m_previous)) * (1 + 1e-9);
  }
  /// Record the lookup at `at`: `found` sorted, `k` asked for.
  void record(const Vec3& at, const std::vector<NeighbourPhoton>& found, std::size_t k) {
    m_previous = at;
    m_short = k > 0 && found.size() < k;
    m_kth_m = found.size() == k && k > 0 ? std::sqrt(found.back().distance_squared_m2)
                                        : std::numeric_limits<double>::quiet_NaN();
  }

 private:
  Vec3 m_previous{0, 0, 0};
  double m_kth_m = std::numeric_limits<double>::quiet_NaN();
  bool m_short = false;
};

/// The curvature correction's pilot (daylight_coefficients.h, "Curvature away from walls"):
/// on a whole disc of radius r, the plane's estimate S0 / (pi r^2) is off by
/// (E_xx + E_yy) r^2 / 8. A quadratic E = b0 + ... + b3 u^2 + b4 u v + b5 v^2 fitted by moments
/// over the whole pilot disc of radius R (u = dx / R) gives b3 + b5 = (24 / pi) sum_j
/// (rho_j^2 - 1/2) Phi_j / R^2 (rho_j = d_j / R: the constant and rho^2 block of the unit
/// disc's moment matrix, [[pi, pi/2], [pi/2, pi/3]], inverted; u^2 - v^2, u v and the odd terms
/// are orthogonal to both), and the bias (b3 + b5) r^2 / (4 R^2). So each pilot photon's
/// weight in the bias is (6 / pi) r^2 (rho_j^2 - 1/2) / R^4, and at R = r the corrected
/// estimate is the quadratic fit's, (4 - 6 rho^2) / (pi r^2).
struct CurvaturePilot {
  double bias_weight = 0;    ///< (6 / pi) r^2 / R^4
  double inv_pilot_m2 = 0;   ///< 1 / R^2
  double weight(double distance_squared_m2) const { return bias_weight * (distance_squared_m2 * inv_pilot_m2 - 0.5); }
};

/// The fewest photons in a disc for the curvature correction at pilot radius R. A corrected
/// total below 0 is clamped (estimate_classes), which biases it upwards where that happens
/// often. Under R = 1.5 r the weights tend to the quadratic's, (4 - 6 rho^2) / (pi r^2), negative
/// over a third of the disc: QuadraticEverywhereMinimumPhotons. From R = 1.5 r the weight of
/// every photon of the kernel disc is at least 1.07 / (pi r^2) and the most negative, on the
/// pilot disc's rim, -3 (r / R)^4 / (pi r^2) >= -0.59 / (pi r^2). The photons of negative
/// weight lie in the pilot disc's outer half, 1.125 times the kernel disc's area at R = 1.5 r:
/// the N photons of the disc outweigh them unless that half holds some 3 times its expected
/// count, so the clamp practically never acts and the full bandwidth is enough.
std::size_t curvature_minimum_photons(double radius_m, double pilot_m) {
  return pilot_m >= 1.5 * radius_m ? 0 : QuadraticEverywhereMinimumPhotons;
}

/// Clamps a negative total (the correction of a small value against its noise) to 0 in both
/// classes, as the quadratic's (local_quadratic_estimate).
void clamp_total(ClassEstimates& e) {
  for (int c = 0; c < 3; ++c)
    if (e.caustic[c] + e.global[c] < 0) {
      e.caustic[c] = 0;
      e.global[c] = 0;
    }
}

/// The largest share of a cut disc's local-linear estimate its curvature correction may
/// subtract or add (subtract_cut_pilot). The correction is the second-order term of the
/// field's Taylor expansion over the disc, read by a quadratic over a pilot twice as wide; where
/// it is not small against the estimate itself (light falling off by orders of magnitude
/// across the disc: closed slats, the back of a deep room), the expansion does not hold at that
/// scale and the terms the quadratic leaves out, which the wider pilot amplifies by (R / r)^k,
/// dominate its reading: the plane is kept. On a narrow shaft's floor the correction is 3-4 %.
constexpr double CutCurvatureLargestShare = 0.5;

/// The curvature correction of a cut disc (local_quadratic_fit.h, cut_curvature_pilot):
/// every photon passing `filter` within the pilot radius, its bias weight subtracted per class
/// from the local-linear estimates in `results` (one per flux of `fluxes`) and from the
/// sub-patch shares; the variance of the difference is var_plane - 2 sum_disc w_lin w_pilot y^2
/// + sum_pilot w_pilot^2 y^2 (the disc's photons are among the pilot's, R >= r). Nothing is
/// done when the pilot is not valid (a region too thin for its fit) or when the correction of
/// the first flux is over CutCurvatureLargestShare of its estimate: the plane stays.
void subtract_cut_pilot(const PhotonMap& map, const Vec3& at, const PhotonFilter& filter,
                        const std::vector<NeighbourPhoton>& found, const KernelDisc& disc,
                        const CutCurvaturePilot& pilot, double pilot_m, const PhotonFlux fluxes[2],
                        ClassEstimates* results[2], int modes, PhotonFlux quadrant_flux,
                        std::vector<NeighbourPhoton>& pilot_found, QuadrantShares* quadrants) {
  if (!pilot.valid) return;
  const double inv_pilot = 1.0 / pilot_m, inv_r = 1.0 / disc.radius_m, inv_r2 = inv_r * inv_r;
  const auto bias_weight = [&](const Photon& ph) {
    return pilot.bias_weight((double(ph.position[0]) - at.x) * inv_pilot, (double(ph.position[1]) - at.y) * inv_pilot);
  };
  map.within(at, pilot_m, filter, pilot_found);
  Vec3 bias[2][2];
  double pilot_variance[2] = {0, 0};
  for (int f = 0; f < modes; ++f) {
    bias[f][0] = bias[f][1] = Vec3{0, 0, 0};
    for (const NeighbourPhoton& n : pilot_found) {
      const Photon& ph = map.photons()[n.index];
      const Vec3 flux = flux_of(ph, fluxes[f]);
      const double w = bias_weight(ph);
      bias[f][ph.path_class == PathClass::Caustic ? 0 : 1] += flux * w;
      const double wy = w * luminance_of(flux);
      pilot_variance[f] += wy * wy;
    }
  }
  const double estimate = luminance_of(results[0]->caustic + results[0]->global);
  if (!(std::fabs(luminance_of(bias[0][0] + bias[0][1])) <= CutCurvatureLargestShare * estimate)) return;
  if (quadrants)
    for (const NeighbourPhoton& n : pilot_found) {
      const Photon& ph = map.photons()[n.index];
      if (ph.sky_quadrant < StoredQuadrants)
        (*quadrants)[ph.sky_quadrant] -= bias_weight(ph) * luminance_of(flux_of(ph, quadrant_flux));
    }
  for (int f = 0; f < modes; ++f) {
    double covariance = 0;
    for (std::size_t j = 0; j < disc.photon_count; ++j) {
      const Photon& ph = map.photons()[found[j].index];
      const double y = luminance_of(flux_of(ph, fluxes[f]));
      const double u = (double(ph.position[0]) - at.x) * inv_r, v = (double(ph.position[1]) - at.y) * inv_r;
      const double w_linear = (pilot.linear[0] + pilot.linear[1] * u + pilot.linear[2] * v) * inv_r2;
      covariance += w_linear * bias_weight(ph) * y * y;
    }
    ClassEstimates& e = *results[f];
    e.caustic -= bias[f][0];
    e.global -= bias[f][1];
    clamp_total(e);
    e.variance = std::max(0.0, e.variance - 2 * covariance + pilot_variance[f]);
  }
}

/// Caustic and global estimates from the photons of `map` passing `filter`, within the disc
/// of density.bandwidth of them (density_estimate.h): local-linear on a receiver plane with
/// the uniform kernel (local-quadratic where the outline cuts the disc, for
/// `quadratic_at_walls`; on every whole disc the curvature correction of
/// options.curvature_correction, its pilot disc no wider than `pilot_limit_m`, the distance
/// from the centre to the nearest boundary, negative for no correction), otherwise the kernel
/// estimate times the boundary factor. `rng_index` seeds the bias-compensating operator.
/// With `weighted`, also the same estimate with every flux times its sky ratio
/// (PhotonFlux::TimesSkyRatio, photon_part_on_sky.h) into it: on the local-linear plane from
/// the same lookups and sums (each value bit for bit what a call with density.flux =
/// TimesSkyRatio gives), elsewhere by that second call.
ClassEstimates estimate_classes(const PhotonMap& map, const ReceiverPlane* plane, const Vec3& at,
                                const PhotonFilter& filter, const DensityEstimateOptions& density,
                                const CoefficientOptions& options, bool quadratic_at_walls, double pilot_limit_m,
                                std::size_t rng_index, LookupHint& hint, std::vector<NeighbourPhoton>& found,
                                std::vector<NeighbourPhoton>& pilot_found, ClassEstimates* weighted = nullptr,
                                QuadrantShares* quadrants = nullptr) {
  ClassEstimates out;
  if (weighted) *weighted = ClassEstimates{};
  if (quadrants) quadrants->fill(0.0);
  if (plane && options.local_linear && !options.bias_compensation && density.kernel == KernelType::Uniform) {
    const std::size_t k = neighbours_needed(density.bandwidth, density.radius);
    map.nearest(at, k, density.max_radius_m, hint.radius_m(at, density.max_radius_m), filter, found);
    hint.record(at, found, k);
    const KernelDisc disc = kernel_disc(found, density.bandwidth, density.radius, density.max_radius_m);
    if (disc.photon_count == 0) return out;
    // The region the disc's photons come from: the disc clipped to the outline, or the part
    // of it the centre sees (filter.visibility, which the lookup applied).
    // The curvature correction on a whole disc (none of it cut) that holds its whole
    // bandwidth, and enough photons (a short disc, a sparse source's, keeps the plane: few
    // photons under the correction's negative lobes would make its clamp at 0 bias it
    // upwards); the local-quadratic fit on a cut disc for the sources of quadratic_at_walls.
    const PlaneVisibility* visible = filter.visibility;
    const CurvatureCorrection curvature = pilot_limit_m >= 0 ? options.curvature_correction : CurvatureCorrection::None;
    const AreaMoments m =
        visible ? visible->moments(disc.radius_m) : plane->clipped_disc_moments(at.x, at.y, disc.radius_m);
    const bool cut = disc.radius_m > 0 && m.area < Pi * disc.radius_m * disc.radius_m * (1 - 1e-9);
    const bool whole = curvature != CurvatureCorrection::None && disc.radius_m > 0 && !cut &&
                       disc.photon_count >= density.bandwidth;
    const double pilot_m = curvature == CurvatureCorrection::Pilot
                               ? std::max(disc.radius_m, std::min({CurvaturePilotRadiusFactor * disc.radius_m,
                                                                   pilot_limit_m, density.max_radius_m}))
                               : disc.radius_m;
    const bool corrected = whole && disc.photon_count >= curvature_minimum_photons(disc.radius_m, pilot_m);
    // A cut disc (not the quadratic's) that holds its whole bandwidth, and at least the
    // quadratic's fewest photons (the clipped pilot's weights have negative lobes that the
    // clamp at 0 would otherwise bias upwards), gets the pilot correction with the pilot clipped
    // by the same walls and cuts (cut_curvature_pilot): R = CurvaturePilotRadiusFactor r within
    // the widest disc, the clip keeping it off what the centre does not see.
    const double cut_pilot_m = std::max(disc.radius_m, std::min(CurvaturePilotRadiusFactor * disc.radius_m,
                                                                density.max_radius_m));
    const bool cut_corrected = curvature == CurvatureCorrection::Pilot && cut && !quadratic_at_walls &&
                               disc.photon_count >= density.bandwidth &&
                               disc.photon_count >= QuadraticEverywhereMinimumPhotons;
    if ((corrected && curvature == CurvatureCorrection::Quadratic) || (quadratic_at_walls && cut)) {
      const LocalQuadraticKernel kernel = local_quadratic_kernel(
          visible ? visible->moments4(disc.radius_m) : plane->clipped_disc_moments4(at.x, at.y, disc.radius_m));
      if (kernel.valid) {
        if (weighted) *weighted = local_quadratic_estimate(map, at, found, disc, kernel, PhotonFlux::TimesSkyRatio);
        if (quadrants)
          for (std::size_t q = 0; q < StoredQuadrants; ++q) {
            const ClassEstimates e = local_quadratic_estimate(map, at, found, disc, kernel, in_sky_quadrant(q));
            (*quadrants)[q] = luminance_of(e.caustic + e.global);
          }
        return local_quadratic_estimate(map, at, found, disc, kernel, density.flux);
      }
    }
    // Per flux (density.flux, then the ratio-weighted one if asked for): the sums of the fit.
    const PhotonFlux fluxes[2] = {density.flux, PhotonFlux::TimesSkyRatio};
    ClassEstimates* results[2] = {&out, weighted};
    const int modes = weighted ? 2 : 1;
    Vec3 s0[2][2], s1x[2][2], s1y[2][2];
    double q[2][6];
    // The sub-patch shares' sums: per sky quadrant the luminance of density.flux (both classes).
    double q0[4] = {0, 0, 0, 0}, q1x[4] = {0, 0, 0, 0}, q1y[4] = {0, 0, 0, 0};
    for (int f = 0; f < 2; ++f) {
      for (int c = 0; c < 2; ++c) s0[f][c] = s1x[f][c] = s1y[f][c] = Vec3{0, 0, 0};
      for (double& x : q[f]) x = 0;
    }
    for (std::size_t j = 0; j < disc.photon_count; ++j) {
      const Photon& ph = map.photons()[found[j].index];
      const int c = ph.path_class == PathClass::Caustic ? 0 : 1;
      const double dx = double(ph.position[0]) - at.x, dy = double(ph.position[1]) - at.y;
      if (quadrants) {
        const double y = luminance_of(flux_of(ph, density.flux));
        q0[ph.sky_quadrant] += y;
        q1x[ph.sky_quadrant] += y * dx;
        q1y[ph.sky_quadrant] += y * dy;
      }
      for (int f = 0; f < modes; ++f) {
        const Vec3 flux = flux_of(ph, fluxes[f]);
        s0[f][c] += flux;
        s1x[f][c] += flux * dx;
        s1y[f][c] += flux * dy;
        const double y2 = luminance_of(flux) * luminance_of(flux);
        q[f][0] += y2;
        q[f][1] += y2 * dx;
        q[f][2] += y2 * dy;
        q[f][3] += y2 * dx * dx;
        q[f][4] += y2 * dx * dy;
        q[f][5] += y2 * dy * dy;
      }
    }
    for (int f = 0; f < modes; ++f) {
      results[f]->caustic = local_linear_density(m, s0[f][0], s1x[f][0], s1y[f][0]);
      results[f]->global = local_linear_density(m, s0[f][1], s1x[f][1], s1y[f][1]);
      results[f]->variance = local_linear_variance(m, q[f]);
    }
    if (quadrants)
      for (std::size_t x = 0; x < StoredQuadrants; ++x)
        (*quadrants)[x] = local_linear_density(m, Vec3{q0[x], 0, 0}, Vec3{q1x[x], 0, 0}, Vec3{q1y[x], 0, 0}).x;
    if (cut_corrected)
      subtract_cut_pilot(map, at, filter, found, disc,
                         cut_curvature_pilot(visible ? visible->moments4(disc.radius_m)
                                                     : plane->clipped_disc_moments4(at.x, at.y, disc.radius_m),
                                             visible ? visible->moments4(cut_pilot_m)
                                                     : plane->clipped_disc_moments4(at.x, at.y, cut_pilot_m),
                                             disc.radius_m, cut_pilot_m),
                         cut_pilot_m, fluxes, results, modes, density.flux, pilot_found, quadrants);
    if (!(corrected && curvature == CurvatureCorrection::Pilot)) return out;
    // The pilot's bias, subtracted per class; the variance of the difference: the plane's
    // weight on a whole disc is 1 / area for each of its photons, so
    // var = var_plane - 2 sum_disc w_pilot y^2 / area + sum_pilot w_pilot^2 y^2.
    CurvaturePilot pilot;
    pilot.inv_pilot_m2 = 1.0 / (pilot_m * pilot_m);
    pilot.bias_weight = 6.0 / Pi * disc.radius_m * disc.radius_m * pilot.inv_pilot_m2 * pilot.inv_pilot_m2;
    map.within(at, pilot_m, filter, pilot_found);
    if (quadrants)
      for (const NeighbourPhoton& n : pilot_found) {
        const Photon& ph = map.photons()[n.index];
        if (ph.sky_quadrant < StoredQuadrants)
          (*quadrants)[ph.sky_quadrant] -= pilot.weight(n.distance_squared_m2) * luminance_of(flux_of(ph, density.flux));
      }
    for (int f = 0; f < modes; ++f) {
      Vec3 bias[2] = {Vec3{0, 0, 0}, Vec3{0, 0, 0}};
      double pilot_variance = 0;
      for (const NeighbourPhoton& n : pilot_found) {
        const Photon& ph = map.photons()[n.index];
        const Vec3 flux = flux_of(ph, fluxes[f]);
        const double w = pilot.weight(n.distance_squared_m2);
        bias[ph.path_class == PathClass::Caustic ? 0 : 1] += flux * w;
        const double wy = w * luminance_of(flux);
        pilot_variance += wy * wy;
      }
      double covariance = 0;
      for (std::size_t j = 0; j < disc.photon_count; ++j) {
        const double y = luminance_of(flux_of(map.photons()[found[j].index], fluxes[f]));
        covariance += pilot.weight(found[j].distance_squared_m2) * y * y;
      }
      ClassEstimates& e = *results[f];
      e.caustic -= bias[0];
      e.global -= bias[1];
      clamp_total(e);
      e.variance = std::max(0.0, e.variance - 2 * covariance / m.area + pilot_variance);
    }
    return out;
  }
  if (weighted) {
    DensityEstimateOptions times_ratio = density;
    times_ratio.flux = PhotonFlux::TimesSkyRatio;
    LookupHint unused = hint;
    *weighted = estimate_classes(map, plane, at, filter, times_ratio, options, quadratic_at_walls, pilot_limit_m,
                                 rng_index, unused, found, pilot_found);
  }
  if (quadrants)
    for (std::size_t q = 0; q < StoredQuadrants; ++q) {
      DensityEstimateOptions in_quadrant = density;
      in_quadrant.flux = in_sky_quadrant(q);
      LookupHint unused = hint;
      const ClassEstimates e = estimate_classes(map, plane, at, filter, in_quadrant, options, quadratic_at_walls,
                                                pilot_limit_m, rng_index, unused, found, pilot_found);
      (*quadrants)[q] = luminance_of(e.caustic + e.global);
    }
  const DensityEstimate all =
      options.bias_compensation
          ? estimate_irradiance_bias_compensated(map, at, filter, bias_options(options, density, rng_index))
          : estimate_irradiance(map, at, filter, density);
  if (all.photon_count == 0) return out;
  // Same disc for each class: a bandwidth one above the count found makes every class
  // lookup a "short" one, whose disc is exactly max_radius_m = all.radius_m. With the
  // next-neighbour radius the (N+1)-th photon lies ON that disc's rim and the fixed-disc
  // lookup (which includes its rim) would count it: shrink the disc by 1e-9 relative (area
  // 2e-9), which leaves it out and changes nothing else.
  DensityEstimateOptions fixed = density;
  fixed.bandwidth = all.photon_count + 1;
  fixed.max_radius_m = density.radius == KernelRadius::NextNeighbour && all.photon_count == density.bandwidth
                           ? all.radius_m * (1 - 1e-9)
                           : all.radius_m;
  fixed.radius = KernelRadius::Plain;
  const double b = options.boundary_correction ? boundary_factor(plane, filter.visibility, at, all.radius_m) : 1.0;
  for (PathClass c : {PathClass::Caustic, PathClass::Global}) {
    PhotonFilter one = filter;
    one.path_classes = static_cast<decltype(one.path_classes)>(filter.path_classes & path_class_bit(c));
    if (one.path_classes == 0) continue;
    const DensityEstimate e = estimate_irradiance(map, at, one, fixed);
    (c == PathClass::Caustic ? out.caustic : out.global) = e.irradiance * b;
    out.variance += e.luminance_variance * b * b;
  }
  return out;
}

}  // namespace

void estimate_photon_coefficients(const GridPhotons& photons,
                                  const std::vector<SensorPoint>& sensors,
                                  const CoefficientOptions& options, DaylightCoefficients& out,
                                  SensorRange rows, DaylightCoefficients* weighted) {
  if (photons.gather())
    throw std::invalid_argument("photon coefficients: gather photons need the scene (photon_coefficients)");
  rows = rows.within(sensors.size());
  const std::size_t n_src = out.sources;
  // Row r of `out` is sensor rows.begin + r; random numbers use the sensor's index s in the
  // whole grid and the whole grid's size (sensor_range.h).
  const std::size_t grid_pairs = sensors.size() * n_src;
  if (out.sensors != rows.size() || out.caustic.size() < rows.size() * n_src || out.global.size() < rows.size() * n_src)
    throw std::invalid_argument("photon coefficients: `out` must hold the " + std::to_string(rows.size()) +
                                " sensors' rows asked for");
  if (out.photon_variance.size() != out.sensors * n_src) out.photon_variance.assign(out.sensors * n_src, 0.0);
  // The photon part's sub-patch shares (CoefficientOptions::photon_quadrants).
  const bool shares = options.photon_quadrants;
  if (shares)
    out.photon_quadrants.assign(out.sensors * n_src * StoredQuadrants, 0.0f);
  else
    out.photon_quadrants.clear();
  auto store_shares = [&](std::size_t i, const QuadrantShares& a, const QuadrantShares* b) {
    for (std::size_t q = 0; q < StoredQuadrants; ++q)
      out.photon_quadrants[i * StoredQuadrants + q] = float(a[q] + (b ? (*b)[q] : 0.0));
  };
  if (weighted) {
    weighted->sensors = out.sensors;
    weighted->sources = n_src;
    weighted->caustic.assign(out.sensors * n_src, Vec3{0, 0, 0});
    weighted->global.assign(out.sensors * n_src, Vec3{0, 0, 0});
    weighted->photon_variance.assign(out.sensors * n_src, 0.0);
  }
  const ReceiverPlane* plane = photons.plane();
  // The widest disc on a receiver plane (sparse sources, header comment); infinite elsewhere.
  const double max_radius_m = std::min(options.density.max_radius_m, photons.max_radius_m(options.density.bandwidth));
  auto filter_for = [&](const SensorPoint& s, PathClass c, const PlaneVisibility* visibility) {
    PhotonFilter f;
    f.path_classes = path_class_bit(c);
    if (!plane) {  // surface photons: only those that arrived on the sensor's side
      f.check_normal = true;
      f.normal = s.normal;
    }
    f.visibility = visibility;
    return f;
  };
  auto query_point = [&](const SensorPoint& sensor) {
    return plane ? Vec3{sensor.position.x, sensor.position.y, plane->height_m()} : sensor.position;
  };
  // The visibility clip (header comment) up to the widest disc any lookup here can have: the
  // maximum radius, at most the outline's diagonal (no photon of the plane lies farther from
  // a sensor inside it).
  const bool clip = plane && options.visibility_clip &&
                    !(plane->interior_cuts().empty() && plane->reflex_vertices().empty());
  double visibility_radius_m = options.estimator == PhotonEstimator::PerSource ? max_radius_m
                                                                               : options.density.max_radius_m;
  if (clip) {
    double min_x = plane->outline()[0].x, max_x = min_x, min_y = plane->outline()[0].y, max_y = min_y;
    for (const PlanePoint& q : plane->outline()) {
      min_x = std::min(min_x, q.x), max_x = std::max(max_x, q.x);
      min_y = std::min(min_y, q.y), max_y = std::max(max_y, q.y);
    }
    visibility_radius_m = std::min(visibility_radius_m, std::hypot(max_x - min_x, max_y - min_y));
  }
  auto visibility_of = [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<std::optional<PlaneVisibility>> v(range.size());
    if (clip)
      for (std::size_t s = range.begin(); s != range.end(); ++s) {
        const Vec3 at = query_point(sensors[s]);
        v[s - range.begin()] = PlaneVisibility::around(*plane, at.x, at.y, visibility_radius_m);
      }
    return v;
  };
  // The curvature correction's limit on the pilot disc (estimate_classes): the distance from
  // each sensor to the nearest outline edge, or cut where the clip bounds the discs, so that
  // the pilot disc is whole.
  const bool correct_curvature = plane && options.curvature_correction != CurvatureCorrection::None;
  auto pilot_limits_of = [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<double> limit_m(range.size(), -1.0);
    if (!correct_curvature) return limit_m;
    const std::vector<PlanePoint>& outline = plane->outline();
    for (std::size_t s = range.begin(); s != range.end(); ++s) {
      const Vec3 at = query_point(sensors[s]);
      double nearest_m = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < outline.size(); ++i)
        nearest_m = std::min(nearest_m, distance_to_segment_m(at.x, at.y, outline[i], outline[(i + 1) % outline.size()]));
      if (clip)
        for (const PlaneSegment& cut : plane->interior_cuts())
          nearest_m = std::min(nearest_m, distance_to_segment_m(at.x, at.y, cut.a, cut.b));
      limit_m[s - range.begin()] = nearest_m;
    }
    return limit_m;
  };
  // Tasks of consecutive sensors, neighbours on the grid. With one map per source, a task
  // goes source by source over its sensors: the source's photons near them stay in the cache
  // from one sensor to the next, and each lookup's hint (LookupHint) comes from the sensor
  // before. Every (sensor, source) estimate is computed alone, so the order changes no value.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(rows.begin, rows.end),
                    [&](const tbb::blocked_range<std::size_t>& range) {
    const std::vector<std::optional<PlaneVisibility>> visibility = visibility_of(range);
    const std::vector<double> pilot_limit_m = pilot_limits_of(range);
    auto visibility_at = [&](std::size_t s) {
      const std::optional<PlaneVisibility>& v = visibility[s - range.begin()];
      return v ? &*v : nullptr;
    };
    if (options.estimator == PhotonEstimator::PerSource) {
      std::vector<NeighbourPhoton> found, pilot_found;
      for (std::size_t p = 0; p < n_src && p < photons.source_count(); ++p) {
        const PhotonMap& map = photons.of_source(p);
        if (map.empty()) continue;
        // Without a caustic map, one lookup over both classes fixes the radius and each class
        // is summed within it. The bandwidth grows with the source's photon count
        // (GridPhotons::bandwidth_of), so a source given more photons (the ground) gets a less
        // noisy estimate, not a smaller kernel.
        DensityEstimateOptions scaled = options.density;
        scaled.bandwidth = photons.bandwidth_of(p, options.density.bandwidth);
        scaled.max_radius_m = max_radius_m;
        DensityEstimateOptions global_scaled = options.density, caustic_scaled = options.density;
        global_scaled.max_radius_m = caustic_scaled.max_radius_m = max_radius_m;
        if (options.caustic_bandwidth > 0) {
          global_scaled.bandwidth = photons.bandwidth_of(p, options.density.bandwidth, PathClass::Global);
          caustic_scaled.bandwidth = photons.bandwidth_of(p, options.caustic_bandwidth, PathClass::Caustic);
        }
        // The local-quadratic fit at walls for the listed sources (header comment), on the
        // lookup of both classes or of the global photons; a caustic map's own discs are sized
        // by the caustic photons' spacing and keep the local-linear fit.
        const bool quadratic = std::find(options.quadratic_fit_sources.begin(), options.quadratic_fit_sources.end(),
                                         p) != options.quadratic_fit_sources.end();
        LookupHint global_hint, caustic_hint;
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
          const SensorPoint& sensor = sensors[s];
          const Vec3 at = query_point(sensor);
          const std::size_t i = (s - rows.begin) * n_src + p;  // in `out`
          const std::size_t stream = s * n_src + p;            // random numbers
          const PlaneVisibility* visible = visibility_at(s);
          const double pilot_m = pilot_limit_m[s - range.begin()];
          ClassEstimates wg, wc;  // with the sky ratios, if asked for
          QuadrantShares qg, qc;  // the sub-patch shares, if asked for
          if (options.caustic_bandwidth == 0) {
            PhotonFilter both = filter_for(sensor, PathClass::Global, visible);
            both.path_classes = IndirectPathClasses;
            const ClassEstimates e = estimate_classes(map, plane, at, both, scaled, options, quadratic, pilot_m,
                                                      stream, global_hint, found, pilot_found, weighted ? &wg : nullptr,
                                                      shares ? &qg : nullptr);
            if (shares) store_shares(i, qg, nullptr);
            out.caustic[i] = e.caustic;
            out.global[i] = e.global;
            out.photon_variance[i] = e.variance;
            if (weighted) {
              weighted->caustic[i] = wg.caustic;
              weighted->global[i] = wg.global;
              weighted->photon_variance[i] = wg.variance;
            }
            continue;
          }
          const ClassEstimates g =
              estimate_classes(map, plane, at, filter_for(sensor, PathClass::Global, visible), global_scaled, options,
                               quadratic, pilot_m, stream, global_hint, found, pilot_found, weighted ? &wg : nullptr,
                               shares ? &qg : nullptr);
          // A caustic map's discs keep the plane (the header comment's "Caustic map").
          const ClassEstimates c =
              estimate_classes(map, plane, at, filter_for(sensor, PathClass::Caustic, visible), caustic_scaled,
                               options, false, -1.0, stream + grid_pairs, caustic_hint, found, pilot_found,
                               weighted ? &wc : nullptr, shares ? &qc : nullptr);
          if (shares) store_shares(i, qg, &qc);
          out.global[i] = g.global;
          out.caustic[i] = c.caustic;
          // Each lookup's photons are of its own class (the filter), so the two are independent.
          out.photon_variance[i] = g.variance + c.variance;
          if (weighted) {
            weighted->global[i] = wg.global;
            weighted->caustic[i] = wc.caustic;
            weighted->photon_variance[i] = wg.variance + wc.variance;
          }
        }
      }
      return;
    }
    // The contribution estimator's rows, made once per task and cleared per lookup: a
    // lookup's per-source sums, and the row the sub-patch passes write and discard.
    std::vector<Vec3> per_source(n_src);
    std::vector<double> per_source_variance(n_src);
    DaylightCoefficients scratch;
    if (shares) {
      scratch.caustic.resize(n_src);
      scratch.global.resize(n_src);
      scratch.photon_variance.resize(n_src);
    }
    for (std::size_t s = range.begin(); s != range.end(); ++s) {
      const SensorPoint& sensor = sensors[s];
      const std::size_t row = s - rows.begin;
      const Vec3 at = query_point(sensor);
      // Passes: the estimate; the ratio-weighted one into `weighted`; the sub-patch shares'.
      const int passes = 2 + (shares ? int(StoredQuadrants) : 0);
      for (int f = 0; f < passes; ++f) {
        if (f == 1 && !weighted) continue;
        for (PathClass c : {PathClass::Caustic, PathClass::Global}) {
          DensityEstimateOptions density = options.density;
          if (f == 1) density.flux = PhotonFlux::TimesSkyRatio;  // the second pass, into `weighted`
          if (f >= 2) density.flux = in_sky_quadrant(std::size_t(f - 2));
          if (f >= 2) {
            std::fill(scratch.caustic.begin(), scratch.caustic.end(), Vec3{0, 0, 0});
            std::fill(scratch.global.begin(), scratch.global.end(), Vec3{0, 0, 0});
            std::fill(scratch.photon_variance.begin(), scratch.photon_variance.end(), 0.0);
          }
          DaylightCoefficients& into = f == 0 ? out : f == 1 ? *weighted : scratch;
          const std::size_t into_row = f >= 2 ? 0 : row;
          if (c == PathClass::Caustic && options.caustic_bandwidth > 0) density.bandwidth = options.caustic_bandwidth;
          std::fill(per_source.begin(), per_source.end(), Vec3{0, 0, 0});
          std::fill(per_source_variance.begin(), per_source_variance.end(), 0.0);
          const DensityEstimate e =
              options.bias_compensation
                  ? estimate_contributions_bias_compensated(
                        photons.all(), at, filter_for(sensor, c, visibility_at(s)),
                        bias_options(options, density, s * 2 + (c == PathClass::Caustic ? 0 : 1)),
                        per_source, &per_source_variance)
                  : estimate_contributions(photons.all(), at, filter_for(sensor, c, visibility_at(s)), density,
                                           per_source, &per_source_variance);
          const double b =
              options.boundary_correction ? boundary_factor(plane, visibility_at(s), at, e.radius_m) : 1.0;
          std::vector<Vec3>& part = c == PathClass::Caustic ? into.caustic : into.global;
          for (std::size_t p = 0; p < n_src; ++p) {
            part[into_row * n_src + p] = per_source[p] * b;
            into.photon_variance[into_row * n_src + p] += per_source_variance[p] * b * b;
          }
          if (f >= 2)
            for (std::size_t p = 0; p < n_src; ++p)
              out.photon_quadrants[(row * n_src + p) * StoredQuadrants + std::size_t(f - 2)] +=
                  float(luminance_of(per_source[p] * b));
        }
      }
    }
  });
}

DaylightCoefficients daylight_coefficients(const Scene& scene,
                                           const std::vector<Material>& materials,
                                           const SourceSet& sources, const GridPhotons& photons,
                                           const std::vector<SensorPoint>& sensors,
                                           const CoefficientOptions& options, SensorRange rows) {
  rows = rows.within(sensors.size());
  DaylightCoefficients c;
  c.sensors = rows.size();
  c.sources = sources.size();
  c.caustic.assign(c.sensors * c.sources, Vec3{0, 0, 0});
  c.global.assign(c.sensors * c.sources, Vec3{0, 0, 0});
  c.direct = direct_coefficients(scene, materials, sources, sensors, options.direct, &c.direct_variance, rows,
                                 &c.direct_on_skies, &c.direct_quadrants);
  photon_coefficients(scene, materials, sources, photons, sensors, options, c, rows);
  return c;
}

void photon_coefficients(const Scene& scene, const std::vector<Material>& materials,
                         const SourceSet& sources, const GridPhotons& photons,
                         const std::vector<SensorPoint>& sensors,
                         const CoefficientOptions& options, DaylightCoefficients& out, SensorRange rows) {
  const std::vector<Vec3>& sky_bins = options.photon_sky_bin_radiance_rgb;
  // The gathered rows' photon part on the sky from the gather's own rays (final_gather.h).
  std::optional<GatherOnSky> gather_sky;
  if (!sky_bins.empty() && options.photon_sky_ratios) gather_sky.emplace(GatherOnSky{*options.photon_sky_ratios, sky_bins});
  const GatherOnSky* on_sky = gather_sky ? &*gather_sky : nullptr;
  // The gather's sub-patch shares with the estimate's (CoefficientOptions::photon_quadrants).
  GatherOptions gather_options = options.gather;
  gather_options.sky_quadrants = options.photon_quadrants;
  if (!photons.gather()) {
    // With the photon part on the sky: the ratio-weighted estimate from the same lookups.
    DaylightCoefficients weighted;
    estimate_photon_coefficients(photons, sensors, options, out, rows, sky_bins.empty() ? nullptr : &weighted);
    const GridPhotons* gather = photons.near_cut_gather();
    rows = rows.within(sensors.size());
    const std::vector<std::size_t> near =
        gather ? sensors_near_cuts(*photons.plane(), sensors, rows) : std::vector<std::size_t>{};
    GatheredCoefficients g;
    if (!near.empty()) {
      // The sensors next to a cut (header comment): their rows replaced by the final gather's.
      // From the sensor's position about its normal, the plane's (SensorGrid::planar).
      g = gather_photon_coefficients_at(scene, materials, sources, gather->all(), sensors, gather_options,
                                        &gather->groups(), near, on_sky);
      const std::size_t n = out.sources;
      for (std::size_t r = 0; r < near.size(); ++r)
        for (std::size_t p = 0; p < n; ++p) {
          const std::size_t i = (near[r] - rows.begin) * n + p;
          out.caustic[i] = g.caustic[r * n + p];
          out.global[i] = g.global[r * n + p];
          out.photon_variance[i] = g.variance[r * n + p];
          if (!out.photon_quadrants.empty())
            for (std::size_t q = 0; q < StoredQuadrants; ++q)
              out.photon_quadrants[i * StoredQuadrants + q] =
                  g.quadrants.empty() ? 0.0f : g.quadrants[(r * n + p) * StoredQuadrants + q];
        }
    }
    // The gathered rows take the gather's estimate on the sky (photon_part_on_sky.h).
    if (!sky_bins.empty())
      out.photon_on_sky = photon_part_on_sky_of(photons, sensors, out, &weighted, sky_bins, rows, &g);
    return;
  }
  GatheredCoefficients g = gather_photon_coefficients(scene, materials, sources, photons.all(), sensors, gather_options,
                                                      &photons.groups(), rows, on_sky);
  out.photon_quadrants = std::move(g.quadrants);
  out.caustic = std::move(g.caustic);
  out.global = std::move(g.global);
  out.photon_variance = std::move(g.variance);
  if (!sky_bins.empty()) out.photon_on_sky = photon_part_on_sky_of(photons, sensors, out, nullptr, sky_bins, rows, &g);
}

}  // namespace dayphoton::engine
