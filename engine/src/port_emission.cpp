// PortEmitter: see port_emission.h for the method and why it is exact.
#include "dayphoton/engine/port_emission.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dayphoton::engine {
namespace {

// Grid used to bound max(-d . n) over a source. -d . n is 1-Lipschitz in the angle of d, and
// every direction of the source lies within one grid spacing (in each of the two parameter
// directions) of a grid node, so the sampled maximum plus twice the largest angle between
// neighbouring nodes is a true bound.
constexpr int BoundGrid = 48;

double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}

}  // namespace

PortEmitter::PortEmitter(const Scene& scene, const SourceSet& sources)
    : m_scene(&scene), m_sources(&sources) {
  const PortSet& ports = scene.ports();
  m_bound_total.assign(sources.size(), 0.0);
  m_cumulative.assign(sources.size(), std::vector<double>(ports.size(), 0.0));
  m_cos_bound.assign(sources.size(), std::vector<double>(ports.size(), 0.0));
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const DistantSource& src = sources[p];
    double running = 0;
    for (std::size_t k = 0; k < ports.size(); ++k) {
      const Vec3 n = ports[k].normal;
      double max_cos = -1, spacing_rad = 0;
      for (int i = 0; i <= BoundGrid; ++i)
        for (int j = 0; j <= BoundGrid; ++j) {
          const double u1 = std::min(double(i) / BoundGrid, 1.0 - 1e-12);
          const double u2 = std::min(double(j) / BoundGrid, 1.0 - 1e-12);
          const Vec3 d = sources.sample_direction(p, u1, u2);
          max_cos = std::max(max_cos, -dot(d, n));
          if (i > 0)
            spacing_rad = std::max(spacing_rad, angle_between(d, sources.sample_direction(
                                                    p, double(i - 1) / BoundGrid, u2)));
          if (j > 0)
            spacing_rad = std::max(spacing_rad, angle_between(d, sources.sample_direction(
                                                    p, u1, double(j - 1) / BoundGrid)));
        }
      const double bound = std::min(1.0, max_cos + 2.0 * spacing_rad);
      m_cos_bound[p][k] = bound > 0 ? bound : 0;
      running += ports[k].area_m2 * src.solid_angle_sr * m_cos_bound[p][k];
      m_cumulative[p][k] = running;
    }
    m_bound_total[p] = running;
  }
}

double PortEmitter::port_flux(std::size_t source, int n) const {
  const PortSet& ports = m_scene->ports();
  const DistantSource& src = (*m_sources)[source];
  double total = 0;
  for (std::size_t k = 0; k < ports.size(); ++k) {
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec3 d = m_sources->sample_direction(source, (i + 0.5) / n, (j + 0.5) / n);
        sum += std::max(0.0, -dot(d, ports[k].normal));
      }
    total += ports[k].area_m2 * src.solid_angle_sr * sum / (double(n) * n);
  }
  return total;
}

std::optional<PortEntry> PortEmitter::attempt(std::size_t source, Rng& rng,
                                              std::uint64_t* rays) const {
  const double total = m_bound_total[source];
  // Always draw the same five numbers so an attempt's randomness does not depend on the
  // outcome of earlier choices.
  const double u_port = rng.uniform(), u_d1 = rng.uniform(), u_d2 = rng.uniform();
  const double u_accept = rng.uniform(), u_p1 = rng.uniform(), u_p2 = rng.uniform();
  if (total <= 0) return std::nullopt;
  const std::vector<double>& cumulative = m_cumulative[source];
  const std::size_t k = static_cast<std::size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), u_port * total) - cumulative.begin());
  if (k >= cumulative.size()) return std::nullopt;
  const Port& port = m_scene->ports()[k];
  const Vec3 d = m_sources->sample_direction(source, u_d1, u_d2);
  const double cos_in = -dot(d, port.normal);
  if (cos_in <= 0 || u_accept * m_cos_bound[source][k] >= cos_in) return std::nullopt;
  const PortSample ps = m_scene->ports().sample(k, u_p1, u_p2);
  // Blocked toward the source? Start just outside the port.
  Ray shadow{m_scene->offset_ray_origin(ps.position, port.normal, d), d, 0.0,
             std::numeric_limits<double>::infinity()};
  if (rays) ++*rays;
  if (m_scene->occluded(shadow)) return std::nullopt;
  return PortEntry{ps.position, d * -1.0, static_cast<int>(k)};
}

}  // namespace dayphoton::engine
