// Direct component: stratified shadow-ray sampling of each distant source from each sensor,
// through straight-transmitting glazing up to the first port (rule and estimator in
// engine/include/dayphoton/engine/direct_component.h; DESIGN.md section 5).
#include "dayphoton/engine/direct_component.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/port_bound.h"
#include "dayphoton/engine/port_view.h"
#include "dayphoton/engine/random.h"

namespace dayphoton::engine {
namespace {

/// Largest double below 1: a jittered stratum coordinate (i + xi) / k can round up to 1.0,
/// which would put the sample on the far edge of the source (outside a half-open bin).
constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

void check_materials(const Scene& scene, const std::vector<Material>& materials) {
  const std::size_t needed = scene.description().materials.size();
  if (materials.size() < needed)
    throw std::invalid_argument("direct component: " + std::to_string(materials.size()) +
                                " material models for a scene with " + std::to_string(needed) +
                                " materials");
}

int strata_per_axis(int samples) {
  if (samples < 1)
    throw std::invalid_argument("direct component: " + std::to_string(samples) +
                                " samples per source; at least 1 is needed");
  int k = static_cast<int>(std::sqrt(static_cast<double>(samples)));
  while (k * k < samples) ++k;
  return k;
}

Vec3 checked_unit_normal(const SensorPoint& sensor) {
  const double len = length(sensor.normal);
  if (!is_finite(sensor.normal) || !(len > 0.0) || !is_finite(sensor.position))
    throw std::invalid_argument(
        "direct component: a sensor needs a finite position and a finite non-zero normal");
  return sensor.normal / len;
}

/// One side of a port cut by the sensor's horizontal plane (header comment): what port
/// sampling draws its points from. A parallelogram with a horizontal edge pair (a vertical
/// or sloped window) stays one, sampled by the aligned map; anything else is a fan of
/// triangles, sampled by area with the square-root warp.
struct PortPiece {
  int port = -1;
  bool below = false;  ///< the part below the sensor's height (directions toward the ground)
  double area_m2 = 0;
  std::optional<std::array<Vec3, 3>> parallelogram;  ///< corner, edge u, edge v
  std::vector<std::array<Vec3, 3>> triangles;
  std::vector<double> cumulative_m2;

  Vec3 point(double u1, double u2) const {
    if (parallelogram) return (*parallelogram)[0] + (*parallelogram)[1] * u1 + (*parallelogram)[2] * u2;
    const double target = u1 * area_m2;
    const std::size_t i = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cumulative_m2.begin(), cumulative_m2.end(), target) - cumulative_m2.begin()),
        triangles.size() - 1);
    const double before = i == 0 ? 0.0 : cumulative_m2[i - 1];
    const double w = std::clamp((target - before) / (cumulative_m2[i] - before), 0.0, 1.0);
    const double r = std::sqrt(w), b0 = 1.0 - r, b1 = u2 * r;
    const std::array<Vec3, 3>& t = triangles[i];
    return t[0] * b0 + t[1] * b1 + t[2] * (1.0 - b0 - b1);
  }
};

/// The part of triangle `t` with z below (or above) `z`, as a fan appended to `out`.
void clip_triangle(const std::array<Vec3, 3>& t, double z, bool below, std::vector<std::array<Vec3, 3>>& out) {
  std::vector<Vec3> poly;
  auto inside = [&](const Vec3& p) { return below ? p.z < z : p.z >= z; };
  for (int i = 0; i < 3; ++i) {
    const Vec3& a = t[static_cast<std::size_t>(i)];
    const Vec3& b = t[static_cast<std::size_t>((i + 1) % 3)];
    if (inside(a)) poly.push_back(a);
    if (inside(a) != inside(b)) poly.push_back(a + (b - a) * ((z - a.z) / (b.z - a.z)));
  }
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) out.push_back({poly[0], poly[i], poly[i + 1]});
}

/// The pieces of every port for a sensor at height z (empty pieces left out).
std::vector<PortPiece> port_pieces(const PortSet& ports, double z) {
  std::vector<PortPiece> pieces;
  for (std::size_t j = 0; j < ports.size(); ++j) {
    const Port& port = ports[j];
    for (bool below : {true, false}) {
      PortPiece piece;
      piece.port = static_cast<int>(j);
      piece.below = below;
      if (port.parallelogram) {
        std::array<Vec3, 3> g = *port.parallelogram;
        if (std::fabs(g[2].z) <= 1e-12 * length(g[2]) && std::fabs(g[1].z) > 1e-12 * length(g[1])) std::swap(g[1], g[2]);
        if (std::fabs(g[1].z) <= 1e-12 * length(g[1])) {
          // Horizontal edge u: z varies along v only, z(v) = z0 + v e_v.z; keep v in [v0, v1].
          const double z0 = g[0].z, dz = g[2].z;
          double v0 = 0, v1 = 1;
          if (dz != 0.0) {
            const double cut = std::clamp((z - z0) / dz, 0.0, 1.0);
            if ((dz > 0) == below) v1 = cut; else v0 = cut;
          } else if ((z0 < z) != below) {
            v1 = 0;  // the whole (horizontal) port lies on the other side
          }
          if (v1 > v0) {
            piece.parallelogram = std::array<Vec3, 3>{g[0] + g[2] * v0, g[1], g[2] * (v1 - v0)};
            piece.area_m2 = port.area_m2 * (v1 - v0);
            pieces.push_back(std::move(piece));
          }
          continue;
        }
      }
      for (const std::array<Vec3, 3>& t : port.triangles) clip_triangle(t, z, below, piece.triangles);
      for (const std::array<Vec3, 3>& t : piece.triangles) {
        piece.area_m2 += 0.5 * length(cross(t[1] - t[0], t[2] - t[0]));
        piece.cumulative_m2.push_back(piece.area_m2);
      }
      if (piece.area_m2 > 1e-12 * port.area_m2) pieces.push_back(std::move(piece));
    }
  }
  return pieces;
}

/// Distance t > 0 at which the ray origin + t w crosses port `port`, or 0 if it does not.
double port_crossing(const Port& port, const Vec3& origin, const Vec3& w) {
  for (const std::array<Vec3, 3>& tri : port.triangles) {
    // Moller-Trumbore, double precision.
    const Vec3 e1 = tri[1] - tri[0], e2 = tri[2] - tri[0];
    const Vec3 pv = cross(w, e2);
    const double det = dot(e1, pv);
    if (det == 0.0) continue;
    const double inv = 1.0 / det;
    const Vec3 tv = origin - tri[0];
    const double u = dot(tv, pv) * inv;
    if (u < 0.0 || u > 1.0) continue;
    const Vec3 qv = cross(tv, e1);
    const double v = dot(w, qv) * inv;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = dot(e2, qv) * inv;
    if (t > 0.0) return t;  // a planar polygon is crossed once
  }
  return 0.0;
}

/// The port pieces on one side of the sensor's height, sampled together: a piece is chosen
/// by area (the first stratified number, rescaled into it, which keeps its strata aligned),
/// so the points are uniform over the side's total area whatever the number of ports.
struct PortSide {
  std::vector<const PortPiece*> pieces;
  std::vector<double> cumulative_m2;
  double area_m2 = 0;

  /// A point uniform by area over the side, and the piece it lies on.
  const PortPiece& choose(double& u1) const {
    const double target = u1 * area_m2;
    const std::size_t i = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cumulative_m2.begin(), cumulative_m2.end(), target) - cumulative_m2.begin()),
        pieces.size() - 1);
    const double before = i == 0 ? 0.0 : cumulative_m2[i - 1];
    u1 = std::clamp((target - before) / (cumulative_m2[i] - before), 0.0, OneMinusEpsilon);
    return *pieces[i];
  }
};

/// Directions per unit solid angle that port sampling produces along `w` from `origin`:
/// sum over the ports j the ray crosses (at t_j > 0) of n_side t_j^2 / (A_side |w . n_j|),
/// the side being that of the sensor's height the crossing lies on. Port `skip` (or -1) is
/// left out.
double port_density(const PortSet& ports, const std::vector<PortBound>& bounds, const PortSide sides[2],
                    const Vec3& origin, const Vec3& w, double n_per_side, int skip) {
  double density = 0;
  for (std::size_t j = 0; j < ports.size(); ++j) {
    if (static_cast<int>(j) == skip) continue;
    const double cos_port = std::fabs(dot(w, ports[j].normal));
    if (!(cos_port > 0)) continue;
    if (!bounds[j].may_cross(origin, w)) continue;  // the same as t = 0 below, cheaper
    const double t = port_crossing(ports[j], origin, w);
    if (!(t > 0)) continue;
    const PortSide& side = sides[w.z < 0 ? 0 : 1];
    if (side.area_m2 > 0) density += n_per_side * t * t / (side.area_m2 * cos_port);
  }
  return density;
}

/// The port side of the balance heuristic, for the solid-angle strata of strategy A.
struct PortSampling {
  const PortSet& ports;
  const std::vector<PortBound>& bounds;
  const PortSide* sides;  ///< [0] below, [1] above the sensor's height
  double n_per_side;
  double density(const Vec3& origin, const Vec3& w) const {
    return port_density(ports, bounds, sides, origin, w, n_per_side, -1);
  }
};

/// The direct irradiance under the continuous skies (header comment, "Continuous skies"):
/// every sample's value per unit radiance, times each sky's radiance at its direction, into
/// one sum per sky, with the variance by the same collapsed strata as the coefficients'.
/// Null when there are no skies: then nothing is evaluated.
class SkyTally {
 public:
  SkyTally(const std::vector<ContinuousSky>& skies, Vec3* sum, double* variance)
      : m_skies(skies), m_sum(sum), m_variance(variance) {}
  /// A new set of strata rows of `row_length` (one source's strata, one side's port points).
  void begin_strata(int row_length) {
    m_strata.clear();
    for (std::size_t k = 0; k < m_skies.size(); ++k) m_strata.emplace_back(row_length, m_variance + k);
  }
  /// The next stratum's sample: direction `w`, value per unit radiance; `credited` false for a
  /// port point that belongs to no source (its value is 0).
  void add(bool credited, const Vec3& w, const Vec3& value) {
    const bool zero = value.x == 0.0 && value.y == 0.0 && value.z == 0.0;
    for (std::size_t k = 0; k < m_skies.size(); ++k) {
      const Vec3 v = zero ? Vec3{} : mul(value, m_skies[k].radiance_rgb(w));
      m_sum[k] += v;
      m_strata[k].add(credited ? 0 : -1, luminance_of(v));
    }
  }

 private:
  const std::vector<ContinuousSky>& m_skies;
  Vec3* m_sum;
  double* m_variance;
  std::vector<StratifiedVariance> m_strata;
};

/// The luminance of a sample's value into its quadrant's share of sky bin p (header comment,
/// "Sub-patch shares"): `shares` holds StoredQuadrants doubles per source, null when not kept;
/// the ground bin keeps none.
void add_to_quadrant(double* shares, std::size_t p, int quadrant, const Vec3& value) {
  if (!shares || p == 0 || quadrant >= static_cast<int>(StoredQuadrants)) return;
  shares[p * StoredQuadrants + static_cast<std::size_t>(quadrant)] += luminance_of(value);
}

/// L(w) T(w) cos: the integrand, L = 1 when `radiance` is null.
Vec3 source_value(const Vec3& t, const Vec3& w, double cos_theta, const std::function<Vec3(const Vec3&)>* radiance) {
  return (radiance ? mul(t, (*radiance)(w)) : t) * cos_theta;
}

/// Stratified samples of source p's solid angle (k x k strata), each weighted by 1 / (its
/// density n_a / Omega_p plus the port sampling's along the same direction, if `ports`):
/// alone (ports null) the plain estimator Omega_p / n sum T cos, else strategy A of the
/// balance heuristic (header comment). `origin` is the sensor already moved off its surface;
/// `view` (or null) the ports seen from it, which rules out shadow rays that cross none.
Vec3 integrate_source_by_solid_angle(const Scene& scene, const std::vector<Material>& materials,
                                     const SourceSet& sources, std::size_t p, const Vec3& origin,
                                     const Vec3& normal, int k, std::uint64_t seed, std::uint64_t sensor_index,
                                     const std::function<Vec3(const Vec3&)>* radiance, const PortSampling* ports,
                                     const PortView* view, double* variance, SkyTally* skies, double* shares) {
  Rng rng(seed, p, sensor_index, RandomStream::Direct);
  const double density_a = static_cast<double>(k) * k / sources[p].solid_angle_sr;
  Vec3 sum;
  StratifiedVariance strata(k, variance);  // along j, row by row (estimate_variance.h)
  if (skies) skies->begin_strata(k);
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      // Draw both numbers before any early exit so that every stratum uses the same pair
      // whatever the scene: glazed and unglazed runs then trace identical directions.
      const double u1 = std::min((i + rng.uniform()) / k, OneMinusEpsilon);
      const double u2 = std::min((j + rng.uniform()) / k, OneMinusEpsilon);
      Vec3 value;
      const Vec3 w = sources.sample_direction(p, u1, u2);
      const double cos_theta = dot(w, normal);
      // A direction the view rules out crosses no port: its sky transmittance is zero
      // (port_view.h), so the shadow ray is not traced and the value stays zero.
      if (cos_theta > 0.0 && (!view || view->may_cross_port(w, 0.0))) {
        const Vec3 t = sky_transmittance(scene, materials, origin, w);
        if (t.x != 0.0 || t.y != 0.0 || t.z != 0.0)
          value = source_value(t, w, cos_theta, radiance) *
                  (1.0 / (density_a + (ports ? ports->density(origin, w) : 0.0)));
      }
      sum += value;
      if (variance) strata.add(0, luminance_of(value));
      if (skies) skies->add(true, w, value);
      add_to_quadrant(shares, p, 2 * static_cast<int>(u1 >= 0.5) + static_cast<int>(u2 >= 0.5), value);
    }
  }
  return sum;
}

/// One sensor's row, every source at once, by multiple importance sampling (header comment):
/// k x k strata over each source's solid angle and kb x kb stratified points on every port
/// piece, combined with the balance heuristic.
void integrate_sensor_mis(const Scene& scene, const std::vector<Material>& materials,
                          const SourceSet& sources, const Vec3& origin, const Vec3& normal, int k,
                          int kb, std::uint64_t seed, std::uint64_t sensor_index,
                          const std::function<Vec3(const Vec3&)>* radiance, const PortView* view, Vec3* row,
                          double* variance_row, SkyTally* skies, double* shares) {
  const PortSet& ports = scene.ports();
  const std::vector<PortPiece> pieces = port_pieces(ports, origin.z);
  PortSide sides[2];  // [0] below the sensor's height, [1] above
  for (const PortPiece& piece : pieces) {
    PortSide& side = sides[piece.below ? 0 : 1];
    side.pieces.push_back(&piece);
    side.area_m2 += piece.area_m2;
    side.cumulative_m2.push_back(side.area_m2);
  }
  const double n_a = static_cast<double>(k) * k, n_b = static_cast<double>(kb) * kb;
  const std::vector<PortBound> bounds = port_bounds(ports);
  const PortSampling port_sampling{ports, bounds, sides, n_b};
  // Strategy A: each source's own solid angle (the same directions as without ports).
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const bool with_ports = sources[p].solid_angle_sr >= PortSampledMinimumSolidAngle_sr;
    row[p] += integrate_source_by_solid_angle(scene, materials, sources, p, origin, normal, k, seed, sensor_index,
                                              radiance, with_ports ? &port_sampling : nullptr, view,
                                              variance_row ? variance_row + p : nullptr, skies, shares);
  }
  // Strategy B: points uniform over each side's port pieces, each direction credited to the
  // source containing it.
  for (int side_index = 0; side_index < 2; ++side_index) {
    const PortSide& side = sides[side_index];
    if (side.pieces.empty()) continue;
    Rng rng(seed, static_cast<std::uint64_t>(side_index), sensor_index, RandomStream::DirectPort);
    // Each point credited to its source (estimate_variance.h).
    StratifiedVariance strata(kb, variance_row);
    if (skies) skies->begin_strata(kb);
    // One port point: the source it is credited to (-1: none), its value and direction.
    auto sample = [&](double u1, double u2, Vec3& value, Vec3& w) -> int {
      const PortPiece& piece = side.choose(u1);
      const Port& port = ports[static_cast<std::size_t>(piece.port)];
      const Vec3 to = piece.point(u1, u2) - origin;
      const double d2 = dot(to, to);
      if (!(d2 > 0.0)) return -1;
      w = to / std::sqrt(d2);
      const double cos_theta = dot(w, normal);
      const double cos_port = std::fabs(dot(w, port.normal));
      if (!(cos_theta > 0.0) || !(cos_port > 0.0)) return -1;
      const int p = sources.find(w);
      if (p < 0 || sources[static_cast<std::size_t>(p)].solid_angle_sr < PortSampledMinimumSolidAngle_sr) return -1;
      const Vec3 t = sky_transmittance(scene, materials, origin, w);
      if (t.x == 0.0 && t.y == 0.0 && t.z == 0.0) return -1;
      // This port's own density analytically (the point lies on it by construction).
      const double density = n_a / sources[static_cast<std::size_t>(p)].solid_angle_sr +
                             n_b * d2 / (side.area_m2 * cos_port) +
                             port_density(ports, bounds, sides, origin, w, n_b, piece.port);
      value = source_value(t, w, cos_theta, radiance) * (1.0 / density);
      return p;
    };
    for (int i = 0; i < kb; ++i) {
      for (int j = 0; j < kb; ++j) {
        const double u1 = std::min((i + rng.uniform()) / kb, OneMinusEpsilon);
        const double u2 = std::min((j + rng.uniform()) / kb, OneMinusEpsilon);
        Vec3 value, w;
        const int p = sample(u1, u2, value, w);
        if (p >= 0) {
          row[static_cast<std::size_t>(p)] += value;
          if (shares && p > 0) add_to_quadrant(shares, static_cast<std::size_t>(p), sources.basis().quadrant(p, w), value);
        }
        if (variance_row) strata.add(p, luminance_of(value));
        if (skies) skies->add(p >= 0, w, p >= 0 ? value : Vec3{});
      }
    }
  }
}

/// One sensor's row: by multiple importance sampling when port sampling is on and the
/// scene has ports, by each source's solid angle alone otherwise.
void integrate_sensor(const Scene& scene, const std::vector<Material>& materials,
                      const SourceSet& sources, const Vec3& origin, const Vec3& normal,
                      const DirectOptions& options, std::uint64_t sensor_index,
                      const std::function<Vec3(const Vec3&)>* radiance, double pad_m, Vec3* row,
                      double* variance_row, SkyTally* skies, double* shares) {
  const int k = strata_per_axis(options.samples_per_source);
  // The ports seen from the sensor: most sampled directions of a deep room meet a ceiling or
  // wall and cross no window, and need no shadow ray (port_view.h). Without ports every ray
  // is traced, as before.
  const std::optional<PortView> view =
      scene.ports().empty() ? std::nullopt : std::optional<PortView>(PortView(scene, origin, pad_m));
  const PortView* seen = view ? &*view : nullptr;
  if (options.port_sampling && !scene.ports().empty()) {
    integrate_sensor_mis(scene, materials, sources, origin, normal, k, PortStrataFactor * k, options.seed,
                         sensor_index, radiance, seen, row, variance_row, skies, shares);
    return;
  }
  for (std::size_t p = 0; p < sources.size(); ++p)
    row[p] += integrate_source_by_solid_angle(scene, materials, sources, p, origin, normal, k, options.seed,
                                              sensor_index, radiance, nullptr, seen,
                                              variance_row ? variance_row + p : nullptr, skies, shares);
}

}  // namespace

SkyPath trace_to_sky(const Scene& scene, const std::vector<Material>& materials,
                     const Vec3& origin, const Vec3& direction) {
  check_materials(scene, materials);
  // Light from the sky propagates toward the sensor, against the shadow ray.
  const Vec3 incoming = -direction;
  SkyPath path;
  path.transmittance = Vec3{1.0, 1.0, 1.0};
  Ray ray;
  ray.origin = origin;
  ray.direction = direction;
  for (int crossings = 0;; ++crossings) {
    const std::optional<Hit> hit = scene.intersect(ray);
    if (!hit) {
      if (path.port < 0) path.transmittance = Vec3{};
      return path;
    }
    // Outside the room nothing is reflected toward the sensor: whatever the ray meets after
    // its port (an obstruction, another building) blocks the sky, except an outdoor
    // scatterer's straight transmission (a glazed canopy), which port emission also leaves
    // to the scatterer (port_emission.h).
    if ((path.port >= 0 && hit->scatterer < 0) || crossings >= MaxShadowRayCrossings) return SkyPath{};
    const Material& material = materials[static_cast<std::size_t>(hit->material)];
    path.transmittance = mul(path.transmittance, material.straight_transmittance(incoming, hit->normal));
    if (!(path.transmittance.x > 0.0 || path.transmittance.y > 0.0 || path.transmittance.z > 0.0))
      return SkyPath{};
    if (hit->port >= 0) path.port = hit->port;
    ray.origin = scene.offset_ray_origin(hit->position, hit->normal, direction);
  }
}

Vec3 sky_transmittance(const Scene& scene, const std::vector<Material>& materials,
                       const Vec3& origin, const Vec3& direction) {
  return trace_to_sky(scene, materials, origin, direction).transmittance;
}

std::vector<Vec3> direct_coefficients(const Scene& scene, const std::vector<Material>& materials,
                                      const SourceSet& sources,
                                      const std::vector<SensorPoint>& sensors,
                                      const DirectOptions& options, std::vector<double>* variance,
                                      SensorRange rows, DirectOnSkies* on_skies, std::vector<float>* quadrants) {
  check_materials(scene, materials);
  (void)strata_per_axis(options.samples_per_source);  // validates the count
  rows = rows.within(sensors.size());
  std::vector<Vec3> normals;
  normals.reserve(rows.size());
  for (std::size_t s = rows.begin; s < rows.end; ++s) normals.push_back(checked_unit_normal(sensors[s]));

  const std::size_t n_sources = sources.size();
  std::vector<Vec3> result(rows.size() * n_sources);
  if (variance) variance->assign(rows.size() * n_sources, 0.0);
  const std::size_t n_skies = on_skies ? options.skies.size() : 0;
  if (on_skies) {
    on_skies->skies = n_skies;
    on_skies->irradiance.assign(rows.size() * n_skies, Vec3{});
    on_skies->variance.assign(rows.size() * n_skies, 0.0);
  }
  const bool with_shares = quadrants && sources.has_basis();
  if (quadrants) quadrants->assign(with_shares ? rows.size() * n_sources * StoredQuadrants : 0, 0.0f);
  const double pad_m = port_view_pad_m(scene, materials);
  // One sensor per task item: each writes only its own row, and its random numbers depend
  // on (seed, source, sensor index in the whole grid) alone, so neither the partition into
  // threads nor the rows asked for change anything.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t r = range.begin(); r != range.end(); ++r) {
                        const std::size_t s = rows.begin + r;
                        const Vec3 origin = sensors[s].position +
                                            normals[r] * scene.ray_epsilon_m();
                        std::optional<SkyTally> skies;
                        if (n_skies > 0)
                          skies.emplace(options.skies, on_skies->irradiance.data() + r * n_skies,
                                        on_skies->variance.data() + r * n_skies);
                        // The shares summed in double, in sample order, then stored as float.
                        std::vector<double> shares(with_shares ? n_sources * StoredQuadrants : 0, 0.0);
                        integrate_sensor(scene, materials, sources, origin, normals[r], options, s,
                                         nullptr, pad_m, result.data() + r * n_sources,
                                         variance ? variance->data() + r * n_sources : nullptr,
                                         skies ? &*skies : nullptr, with_shares ? shares.data() : nullptr);
                        for (std::size_t i = 0; i < shares.size(); ++i)
                          (*quadrants)[r * n_sources * StoredQuadrants + i] = static_cast<float>(shares[i]);
                      }
                    });
  return result;
}

Vec3 direct_irradiance(const Scene& scene, const std::vector<Material>& materials,
                       const SourceSet& sources, const SensorPoint& sensor,
                       const std::function<Vec3(const Vec3&)>& radiance, int samples,
                       std::uint64_t seed, bool port_sampling) {
  check_materials(scene, materials);
  DirectOptions options;
  options.samples_per_source = samples;
  options.seed = seed;
  options.port_sampling = port_sampling;
  (void)strata_per_axis(samples);  // validates the count
  const Vec3 normal = checked_unit_normal(sensor);
  const Vec3 origin = sensor.position + normal * scene.ray_epsilon_m();
  std::vector<Vec3> row(sources.size());
  integrate_sensor(scene, materials, sources, origin, normal, options, 0, &radiance, port_view_pad_m(scene, materials),
                   row.data(), nullptr, nullptr, nullptr);
  Vec3 sum;
  for (const Vec3& v : row) sum += v;
  return sum;
}

}  // namespace dayphoton::engine
