// PortEmitter: photons from distant sources enter through photon ports (seeds/000 section
// 4.1.3, digest section 3.3; DESIGN.md section 5).
//
// For source p (unit radiance over its solid angle Omega_p) and port k (area A_k, unit
// normal n_k into the room) the flux entering is
//     Phi_pk = A_k * integral over Omega_p of max(0, -d . n_k) dd        (d toward the source)
// Emission draws it without quadrature error and with constant photon flux by rejection:
// one ATTEMPT picks port k with probability proportional to its bound B_pk = A_k Omega_p
// c_pk (per cell of the source, see "Cells" below), where c_pk >= max over the source of
// (-d . n_k) (exact for sky bins, a grid bound for sun discs: "The bounds" below), a
// direction d uniform in Omega_p, a point uniform
// on the port, and accepts with probability (-d . n_k) / c_pk. Every accepted photon carries
// the same flux (sum_k B_pk) / attempts, so the expected flux through the ports is exactly
// sum_k Phi_pk. An accepted photon whose path back toward the source is blocked (external
// obstructions, other parts of the building) is dropped: sources are checked for occlusion
// from the port, as in the thesis; there is no external inter-reflection.
//
// Ports must not overlap as seen from a source (one ray's flux would enter twice) and every
// aperture must be a port (light entering elsewhere is lost): the thesis leaves both to the
// user; dayphoton's scene check reports ports, the user marks them.
//
// Outdoor scatterers (Surface::outdoor_scatterer: the parts of exterior daylight systems)
// are emission sites too, one per lit side (both for a thin part, the outside for a face of
// a closed solid: scatterer_sides.h): side s of a scatterer with normal n takes the light
// arriving from directions with d . s > 0 (s = n or -n), exactly as a port whose inward
// normal is -s. A photon accepted there lands on the scatterer (it is scattered by the
// scatterer's material in the tracer) instead of entering a room. Every ray from the sky
// toward the building thus starts its path at its first hit among the ports and scatterers:
// a port's path toward the source that a scatterer blocks is rejected (the scatterer takes
// that light), and a scatterer point that another surface hides from the source is
// rejected too (that surface takes it, if it is a scatterer or a port). Light reflected by
// other outdoor surfaces (ground excepted: it is a source) is still not modelled.
//
// Cells: a large source (a sky bin; the ground bin) is split into C x C cells of equal solid
// angle (C = 8, fewer when a scene has very many sites; its map from (u1, u2) to directions
// preserves solid angle, so a cell is a square of [0, 1)^2), each with its own bound c_pkc;
// the attempt picks (port, cell) with probability proportional to B_pkc = A_k (Omega_p / C^2)
// c_pkc and a direction uniform in that cell. The accepted density stays A_k max(0, -d . n_k)
// per unit bound; only rejections change.
//
// The bounds: for a sky bin, the exact largest cosine over each cell (patch_cosine_bound.h:
// a cell is a rectangle in sin altitude and azimuth) plus 1e-9 for rounding, and 0 for a cell
// that lies behind the port's plane or touches it along an edge, so such a bin costs no
// attempts at all; for a sun disc, the largest cosine over a grid of its directions plus
// twice the grid's spacing. On the office one attempt in 1.17 enters (1 in 3.0 with one grid
// bound per bin).
//
// Set-up cost: the cosine bound of a site depends on its inward normal only; each source's
// direction grid is sampled once and the bound is computed once per distinct normal (the
// slats of a blind share a few), so sites are cheap however many there are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/random.h"
#include "dayphoton/engine/scene.h"

namespace dayphoton::engine {

/// An accepted, unoccluded emission: where the photon meets its port (or lands on an outdoor
/// scatterer) and where it goes.
struct PortEntry {
  Vec3 position;   ///< on the port (or scatterer) polygon, metres
  Vec3 direction;  ///< propagation direction (into the room, or onto the scatterer), unit
  int port = -1;   ///< index into Scene::ports(), or -1 for a scatterer
  int scatterer = -1;  ///< index into Scene::outdoor_scatterers(), or -1 for a port
};

class PortEmitter {
 public:
  /// Throws std::invalid_argument for more than MaxPhotonSources sources (photon.h).
  PortEmitter(const Scene& scene, const SourceSet& sources);

  const SourceSet& sources() const { return *m_sources; }

  /// sum_k B_pk: the flux (per unit source radiance, W per W/(sr m^2)) that one attempt
  /// carries times the number of attempts. Zero if no port faces the source.
  double bound_flux(std::size_t source) const { return m_bound_total[source]; }

  /// The part of bound_flux on the ports (the rest lands on outdoor scatterers).
  double port_bound_flux(std::size_t source) const {
    if (m_port_sites == 0) return 0.0;
    const std::size_t per_site = static_cast<std::size_t>(m_cells[source] * m_cells[source]);
    return m_cumulative[source][m_port_sites * per_site - 1];
  }

  /// sum_k Phi_pk by midpoint quadrature on an n x n grid of the source (tests, reports),
  /// over every site: ports and both sides of every outdoor scatterer.
  double port_flux(std::size_t source, int n = 256) const;

  /// Number of emission sites: the ports, then each lit side of every outdoor scatterer.
  std::size_t site_count() const { return m_sites.size(); }

  /// One emission attempt for `source` using `rng` (RandomStream::Emission). Nothing if the
  /// attempt is rejected or its path toward the source is blocked. `rays`, if given, is
  /// incremented by the number of rays cast (the occlusion test of accepted directions).
  std::optional<PortEntry> attempt(std::size_t source, Rng& rng,
                                   std::uint64_t* rays = nullptr) const;

 private:
  /// A port, or one side of an outdoor scatterer.
  struct Site {
    const PortSet* set = nullptr;    ///< Scene::ports() or Scene::outdoor_scatterers()
    std::size_t index = 0;           ///< in `set`
    Vec3 inward;                     ///< accepts directions d (toward the source) with d . inward < 0
    int port = -1, scatterer = -1;
  };

  const Scene* m_scene;
  const SourceSet* m_sources;
  std::vector<Site> m_sites;  ///< the ports first, then the scatterers' sides
  std::size_t m_port_sites = 0;
  std::vector<double> m_bound_total;            ///< per source
  std::vector<int> m_cells;                     ///< per source: cells per axis C
  /// Per source: running sum of B_pkc over (site, cell), site-major, C^2 cells per site.
  std::vector<std::vector<double>> m_cumulative;
  std::vector<std::vector<double>> m_cos_bound;  ///< per source: c_pkc per (site, cell)
  /// Per source: where to start looking for an attempt's entry (port_emission.cpp).
  std::vector<std::vector<std::uint32_t>> m_guide;
};

}  // namespace dayphoton::engine
