// PortEmitter: photons from distant sources enter through photon ports (seeds/000 section
// 4.1.3, digest section 3.3; DESIGN.md section 5).
//
// For source p (unit radiance over its solid angle Omega_p) and port k (area A_k, unit
// normal n_k into the room) the flux entering is
//     Phi_pk = A_k * integral over Omega_p of max(0, -d . n_k) dd        (d toward the source)
// Emission draws it without quadrature error and with constant photon flux by rejection:
// one ATTEMPT picks port k with probability proportional to its bound B_pk = A_k Omega_p
// c_pk, where c_pk >= max over the source of (-d . n_k) (a sampled maximum plus the grid's
// angular spacing, so it is a true bound), a direction d uniform in Omega_p, a point uniform
// on the port, and accepts with probability (-d . n_k) / c_pk. Every accepted photon carries
// the same flux (sum_k B_pk) / attempts, so the expected flux through the ports is exactly
// sum_k Phi_pk. An accepted photon whose path back toward the source is blocked (external
// obstructions, other parts of the building) is dropped: sources are checked for occlusion
// from the port, as in the thesis; there is no external inter-reflection.
//
// Ports must not overlap as seen from a source (one ray's flux would enter twice) and every
// aperture must be a port (light entering elsewhere is lost): the thesis leaves both to the
// user; dayphoton's scene check reports ports, the user marks them.
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

/// An accepted, unoccluded emission: where the photon meets its port and where it goes.
struct PortEntry {
  Vec3 position;   ///< on the port polygon, metres
  Vec3 direction;  ///< propagation direction (into the room), unit
  int port = -1;   ///< index into Scene::ports()
};

class PortEmitter {
 public:
  PortEmitter(const Scene& scene, const SourceSet& sources);

  /// sum_k B_pk: the flux (per unit source radiance, W per W/(sr m^2)) that one attempt
  /// carries times the number of attempts. Zero if no port faces the source.
  double bound_flux(std::size_t source) const { return m_bound_total[source]; }

  /// sum_k Phi_pk by midpoint quadrature on an n x n grid of the source (tests, reports).
  double port_flux(std::size_t source, int n = 256) const;

  /// One emission attempt for `source` using `rng` (RandomStream::Emission). Nothing if the
  /// attempt is rejected or its path toward the source is blocked. `rays`, if given, is
  /// incremented by the number of rays cast (the occlusion test of accepted directions).
  std::optional<PortEntry> attempt(std::size_t source, Rng& rng,
                                   std::uint64_t* rays = nullptr) const;

 private:
  const Scene* m_scene;
  const SourceSet* m_sources;
  std::vector<double> m_bound_total;            ///< per source
  std::vector<std::vector<double>> m_cumulative; ///< per source: running sum of B_pk over ports
  std::vector<std::vector<double>> m_cos_bound;  ///< per source: c_pk
};

}  // namespace dayphoton::engine
