// PortEmitter: see port_emission.h for the method and why it is exact.
#include "dayphoton/engine/port_emission.h"

#include "dayphoton/engine/photon.h"

#include "dayphoton/engine/patch_cosine_bound.h"
#include "dayphoton/engine/scatterer_sides.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <limits>
#include <map>

namespace dayphoton::engine {
namespace {

// Grid used to bound max(-d . n) over a source. -d . n is 1-Lipschitz in the angle of d, and
// every direction of the source lies within one grid spacing (in each of the two parameter
// directions) of a grid node, so the sampled maximum plus twice the largest angle between
// neighbouring nodes is a true bound. The same holds in each cell of a source (below) with the
// nodes on and inside the cell's border, since cell borders fall on grid lines.
constexpr int BoundGrid = 48;
/// Cells per axis of a large source (each its own bound; BoundGrid must be a multiple). On the
/// office 8 x 8 cells with the exact bounds of sky bins take the attempts per entering photon
/// from 2.70 to 1.17 (docs/photon-tracing.md). An earlier note blamed cells for a wider
/// spread of InteriorGlazing's eight replicate daylight factors; 16 and 32 replicates with
/// other seeds show the same spread with and without cells (standard errors of the mean DF
/// within 10 % of each other), so it was the eight seeds' luck, not the emission.
constexpr int MaxCells = 8;
/// Sources smaller than this get one cell: their cosine varies too little to matter.
constexpr double CellMinimumSolidAngle_sr = 1e-3;
/// Largest sites x cells per source (the per-source tables' length).
constexpr std::size_t CellEntryBudget = 4096;
static_assert(BoundGrid % MaxCells == 0, "cells must split the bound grid evenly");

/// Added to the exact per-cell cosine bound of a sky bin to cover rounding (of the bound and
/// of the sampled direction, a few ulps each); a cell whose largest cosine is at most this is
/// given no attempts: it could send at most 1e-9 A Omega, a billionth of a frontal cell.
constexpr double CosineRounding = 1e-9;
/// Largest double below 1 (a cell coordinate must stay inside the source's map).
constexpr double OneMinusEpsilon = 0x1.fffffffffffffp-1;

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

/// Largest per-cell bound c_pkc for inward normal n: the largest -d . n over the grid nodes
/// of each of the cells x cells cells (boundary nodes included) plus twice the spacing, in
/// [0, 1]; cell c = cell_u1 * cells + cell_u2.
std::vector<double> cell_cos_bounds(const SourceGrid& grid, const Vec3& n, int cells) {
  const int nodes_per_cell = BoundGrid / cells;
  std::vector<double> bounds(static_cast<std::size_t>(cells * cells), -1.0);
  for (int i = 0; i <= BoundGrid; ++i)
    for (int j = 0; j <= BoundGrid; ++j) {
      const double c = -dot(grid.directions[static_cast<std::size_t>(i * (BoundGrid + 1) + j)], n);
      // A node on a cell boundary belongs to the cells on both sides.
      for (int ci = std::max(0, (i - 1) / nodes_per_cell); ci <= std::min(cells - 1, i / nodes_per_cell); ++ci)
        for (int cj = std::max(0, (j - 1) / nodes_per_cell); cj <= std::min(cells - 1, j / nodes_per_cell); ++cj) {
          if (i < ci * nodes_per_cell || i > (ci + 1) * nodes_per_cell) continue;
          if (j < cj * nodes_per_cell || j > (cj + 1) * nodes_per_cell) continue;
          double& b = bounds[static_cast<std::size_t>(ci * cells + cj)];
          b = std::max(b, c);
        }
    }
  for (double& b : bounds) {
    b = std::min(1.0, b + 2.0 * grid.spacing_rad);
    if (!(b > 0)) b = 0;
  }
  return bounds;
}

/// Per-cell bounds c_pkc for inward normal n of a sky bin of the basis: the exact largest
/// -d . n over each cell (patch_cosine_bound.h; a cell of a bin is a rectangle in (sin
/// altitude, azimuth) because the bin's map is linear in both), plus CosineRounding; 0 for
/// a cell whose largest cosine is at most CosineRounding (behind the port's plane, or
/// touching it along an edge: a bin whose edge lies in the plane of a window).
std::vector<double> patch_cell_cos_bounds(const sky::PatchBasis& basis, int bin, const Vec3& n, int cells) {
  const sky::PatchBounds b = basis.bounds(bin);
  const double z0 = std::sin(b.altitude_min_rad), z1 = std::sin(b.altitude_max_rad);
  const double dz = (z1 - z0) / cells, da = (b.azimuth_max_rad - b.azimuth_min_rad) / cells;
  std::vector<double> bounds(static_cast<std::size_t>(cells * cells), 0.0);
  for (int ci = 0; ci < cells; ++ci)
    for (int cj = 0; cj < cells; ++cj) {
      const double top = ci + 1 == cells ? z1 : z0 + (ci + 1) * dz;
      const double right = cj + 1 == cells ? b.azimuth_max_rad : b.azimuth_min_rad + (cj + 1) * da;
      const double c = max_cosine_over_patch(n * -1.0, z0 + ci * dz, top, b.azimuth_min_rad + cj * da, right);
      bounds[static_cast<std::size_t>(ci * cells + cj)] = c > CosineRounding ? std::min(1.0, c + CosineRounding) : 0.0;
    }
  return bounds;
}

/// Bound c_pk for inward normal n of a disc source drawn as one cell: the exact largest
/// -d . n over the cone of half-angle a around the centre c, cos(max(0, angle(c, -n) - a))
/// (the directions of the cone nearest -n lie on the great circle through c and -n), plus
/// CosineRounding; 0 when that is at most CosineRounding (the disc is behind the plane).
std::vector<double> disc_cos_bound(const DistantSource& src, const Vec3& n) {
  const Vec3 m = n * -1.0;
  const double apart = std::max(0.0, angle_between(src.direction, m) - src.half_angle_rad);
  const double c = std::cos(apart);
  return {c > CosineRounding ? std::min(1.0, c + CosineRounding) : 0.0};
}

/// Cells per axis of source `p` (port_emission.h, "Cells"): 1 for a small source, else as
/// many as the entry budget allows for `sites` sites, at most MaxCells.
int cells_for(const SourceSet& sources, std::size_t p, std::size_t sites) {
  if (sources[p].solid_angle_sr < CellMinimumSolidAngle_sr) return 1;
  int cells = MaxCells;
  while (cells > 1 && sites * static_cast<std::size_t>(cells * cells) > CellEntryBudget) cells /= 2;
  return cells;
}

}  // namespace

PortEmitter::PortEmitter(const Scene& scene, const SourceSet& sources)
    : m_scene(&scene), m_sources(&sources) {
  if (sources.size() > MaxPhotonSources)
    throw std::invalid_argument("photon emission: " + std::to_string(sources.size()) + " sources, but a photon record names at most " +
                                std::to_string(MaxPhotonSources));
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
  m_cells.assign(sources.size(), 1);
  m_cumulative.assign(sources.size(), {});
  m_cos_bound.assign(sources.size(), {});
  m_guide.assign(sources.size(), {});
  for (std::size_t p = 0; p < sources.size(); ++p) {
    const DistantSource& src = sources[p];
    // Sky bins: the exact bound per cell; sun discs: the bound from the direction grid.
    const bool patch = src.kind == SourceKind::SkyBin && sources.has_basis();
    const int cells = cells_for(sources, p, m_sites.size());
    // A sun disc drawn whole: the exact bound of its cone (disc_cos_bound), no grid.
    const bool disc = src.kind == SourceKind::SunDisc && cells == 1;
    const SourceGrid grid = patch || disc ? SourceGrid{} : source_grid(sources, p);
    const std::size_t per_site = static_cast<std::size_t>(cells * cells);
    m_cells[p] = cells;
    m_cumulative[p].assign(m_sites.size() * per_site, 0.0);
    m_cos_bound[p].assign(m_sites.size() * per_site, 0.0);
    // The bound depends on the inward normal alone: computed once per distinct normal.
    std::map<std::array<double, 3>, std::vector<double>> by_normal;
    double running = 0;
    for (std::size_t k = 0; k < m_sites.size(); ++k) {
      const Vec3& n = m_sites[k].inward;
      const auto [it, fresh] = by_normal.try_emplace({n.x, n.y, n.z});
      if (fresh)
        it->second = patch  ? patch_cell_cos_bounds(sources.basis(), src.bin, n, cells)
                     : disc ? disc_cos_bound(src, n)
                            : cell_cos_bounds(grid, n, cells);
      // Each cell covers Omega_p / cells^2: the source maps (u1, u2) area-preservingly.
      const double cell_flux = (*m_sites[k].set)[m_sites[k].index].area_m2 * src.solid_angle_sr / double(per_site);
      for (std::size_t c = 0; c < per_site; ++c) {
        m_cos_bound[p][k * per_site + c] = it->second[c];
        running += cell_flux * it->second[c];
        m_cumulative[p][k * per_site + c] = running;
      }
    }
    m_bound_total[p] = running;
    // Guide table (Chen and Asau, "On generating random variates from an empirical
    // distribution", AIIE Transactions 6(2), 1974): guide[m] is the first entry whose running sum exceeds a value a
    // little below m / M of the total, so the search from there finds what upper_bound over
    // the whole table finds, in about one step. The slack covers the rounding of u * M and
    // u * total (a few ulps).
    const std::vector<double>& cumulative = m_cumulative[p];
    std::vector<std::uint32_t>& guide = m_guide[p];
    guide.resize(cumulative.size());
    for (std::size_t m = 0; m < guide.size(); ++m) {
      const double below = double(m) / double(guide.size()) * running * (1.0 - 1e-9);
      guide[m] = static_cast<std::uint32_t>(std::upper_bound(cumulative.begin(), cumulative.end(), below) -
                                            cumulative.begin());
    }
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
  // The first entry whose running sum exceeds u_port * total (upper_bound), from the guide.
  const std::vector<std::uint32_t>& guide = m_guide[source];
  const double target = u_port * total;
  std::size_t entry = guide[std::min(guide.size() - 1, static_cast<std::size_t>(u_port * double(guide.size())))];
  while (entry < cumulative.size() && !(cumulative[entry] > target)) ++entry;
  if (entry >= cumulative.size()) return std::nullopt;
  const int cells = m_cells[source];
  const std::size_t per_site = static_cast<std::size_t>(cells * cells);
  const std::size_t k = entry / per_site, cell = entry % per_site;
  const Site& site = m_sites[k];
  const double u1 = std::min((double(cell / static_cast<std::size_t>(cells)) + u_d1) / cells, OneMinusEpsilon);
  const double u2 = std::min((double(cell % static_cast<std::size_t>(cells)) + u_d2) / cells, OneMinusEpsilon);
  const Vec3 d = m_sources->sample_direction(source, u1, u2);
  const double cos_in = -dot(d, site.inward);
  if (cos_in <= 0 || u_accept * m_cos_bound[source][entry] >= cos_in) return std::nullopt;
  const PortSample ps = site.set->sample(site.index, u_p1, u_p2);
  // Blocked toward the source? Start just off the site, on the source's side.
  Ray shadow{m_scene->offset_ray_origin(ps.position, site.inward, d), d, 0.0,
             std::numeric_limits<double>::infinity()};
  if (rays) ++*rays;
  if (m_scene->occluded(shadow)) return std::nullopt;
  return PortEntry{ps.position, d * -1.0, site.port, site.scatterer};
}

}  // namespace dayphoton::engine
