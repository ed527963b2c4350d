// PortEmitter: see port_emission.h for the method and why it is exact.
#include "dayphoton/engine/port_emission.h"

#include "dayphoton/engine/scatterer_sides.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

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

/// A source's direction grid and the largest angle between neighbouring nodes.
struct SourceGrid {
  std::vector<Vec3> directions;
  double spacing_rad = 0;
};

SourceGrid source_grid(const SourceSet& sources, std::size_t p) {
  SourceGrid grid;
  grid.directions.reserve((BoundGrid + 1) * (BoundGrid + 1));
  for (int i = 0; i <= BoundGrid; ++i)
    for (int j = 0; j <= BoundGrid; ++j) {
      const double u1 = std::min(double(i) / BoundGrid, 1.0 - 1e-12);
      const double u2 = std::min(double(j) / BoundGrid, 1.0 - 1e-12);
      const Vec3 d = sources.sample_direction(p, u1, u2);
      grid.directions.push_back(d);
      if (i > 0)
        grid.spacing_rad = std::max(grid.spacing_rad, angle_between(d, sources.sample_direction(
                                                          p, double(i - 1) / BoundGrid, u2)));
      if (j > 0)
        grid.spacing_rad = std::max(grid.spacing_rad, angle_between(d, sources.sample_direction(
                                                          p, u1, double(j - 1) / BoundGrid)));
    }
  return grid;
}

/// c_pk for inward normal n: the grid's largest -d . n plus twice its spacing, in [0, 1].
double cos_bound(const SourceGrid& grid, const Vec3& n) {
  double max_cos = -1;
  for (const Vec3& d : grid.directions) max_cos = std::max(max_cos, -dot(d, n));
  const double bound = std::min(1.0, max_cos + 2.0 * grid.spacing_rad);
  return bound > 0 ? bound : 0;
}

}  // namespace

PortEmitter::PortEmitter(const Scene& scene, const SourceSet& sources)
    : m_scene(&scene), m_sources(&sources) {
  const PortSet& ports = scene.ports();
  for (std::size_t k = 0; k < ports.size(); ++k)
    m_sites.push_back(Site{&ports, k, ports[k].normal, static_cast<int>(k), -1});
  m_port_sites = m_sites.size();
  const PortSet& scatterers = scene.outdoor_scatterers();
  std::vector<int> scatterer_surfaces;
  for (const Port& s : scatterers.ports()) scatterer_surfaces.push_back(s.surface);
  const std::vector<LitSides> lit = scatterer_lit_sides(scene.description(), scatterer_surfaces);
  for (std::size_t k = 0; k < scatterers.size(); ++k) {
    // The front side (light from d . n > 0) accepts like a port whose inward normal is -n.
    if (lit[k] != LitSides::Back)
      m_sites.push_back(Site{&scatterers, k, scatterers[k].normal * -1.0, -1, static_cast<int>(k)});
    if (lit[k] != LitSides::Front)
      m_sites.push_back(Site{&scatterers, k, scatterers[k].normal, -1, static_cast<int>(k)});
  }
  m_bound_total.assign(sources.size(), 0.0);
  m_cumulative.assign(sources.size(), std::vector<double>(m_sites.size(), 0.0));
  m_cos_bound.assign(sources.size(), std::vector<double>(m_sites.size(), 0.0));
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const DistantSource& src = sources[p];
    const SourceGrid grid = source_grid(sources, p);
    // The bound depends on the inward normal alone: computed once per distinct normal.
    std::map<std::array<double, 3>, double> by_normal;
    double running = 0;
    for (std::size_t k = 0; k < m_sites.size(); ++k) {
      const Vec3& n = m_sites[k].inward;
      const auto [it, fresh] = by_normal.try_emplace({n.x, n.y, n.z}, 0.0);
      if (fresh) it->second = cos_bound(grid, n);
      m_cos_bound[p][k] = it->second;
      running += (*m_sites[k].set)[m_sites[k].index].area_m2 * src.solid_angle_sr * m_cos_bound[p][k];
      m_cumulative[p][k] = running;
    }
    m_bound_total[p] = running;
  }
}

double PortEmitter::port_flux(std::size_t source, int n) const {
  const DistantSource& src = (*m_sources)[source];
  double total = 0;
  for (const Site& site : m_sites) {
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec3 d = m_sources->sample_direction(source, (i + 0.5) / n, (j + 0.5) / n);
        sum += std::max(0.0, -dot(d, site.inward));
      }
    total += (*site.set)[site.index].area_m2 * src.solid_angle_sr * sum / (double(n) * n);
  }
  return total;
}

std::optional<PortEntry> PortEmitter::attempt(std::size_t source, Rng& rng,
                                              std::uint64_t* rays) const {
  const double total = m_bound_total[source];
  // Always draw the same six numbers so an attempt's randomness does not depend on the
  // outcome of earlier choices.
  const double u_port = rng.uniform(), u_d1 = rng.uniform(), u_d2 = rng.uniform();
  const double u_accept = rng.uniform(), u_p1 = rng.uniform(), u_p2 = rng.uniform();
  if (total <= 0) return std::nullopt;
  const std::vector<double>& cumulative = m_cumulative[source];
  const std::size_t k = static_cast<std::size_t>(
      std::upper_bound(cumulative.begin(), cumulative.end(), u_port * total) - cumulative.begin());
  if (k >= cumulative.size()) return std::nullopt;
  const Site& site = m_sites[k];
  const Vec3 d = m_sources->sample_direction(source, u_d1, u_d2);
  const double cos_in = -dot(d, site.inward);
  if (cos_in <= 0 || u_accept * m_cos_bound[source][k] >= cos_in) return std::nullopt;
  const PortSample ps = site.set->sample(site.index, u_p1, u_p2);
  // Blocked toward the source? Start just off the site, on the source's side.
  Ray shadow{m_scene->offset_ray_origin(ps.position, site.inward, d), d, 0.0,
             std::numeric_limits<double>::infinity()};
  if (rays) ++*rays;
  if (m_scene->occluded(shadow)) return std::nullopt;
  return PortEntry{ps.position, d * -1.0, site.port, site.scatterer};
}

}  // namespace dayphoton::engine
