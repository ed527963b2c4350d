// RoundGridMaps: the photon maps of one accuracy round's grids, made from the round's photons
// (round_photons) without copying them. Every grid that reads the surface photons (a final
// gather, or sensors on surfaces: the same for every such grid of a case) shares one map, and
// each receiver plane's photons make the map of the grid on that plane; the photons are moved
// into the map that reads them, which is built on first use (LazyValue: only in a process that
// estimates some block of a grid that reads it) and released after the last grid that reads it
// (done). A round then holds its records and one scaled copy of their photons, in the maps,
// where each grid used to copy the surface photons into a map of its own (29 M photons, 0.9 GB
// a copy, on projects/honeybee at the default accuracy: docs/photon-tracing.md "Scale").
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/receiver_plane.h"

namespace dayphoton::study {

class RoundGridMaps {
 public:
  /// `plane_of_grid[g]`: grid g's receiver plane, or -1 for a grid on the surface photons (a
  /// final gather when `gather`, else the surface estimate); `scale`: each source's photon
  /// count relative to the reference (GridPhotons::set_source_scale, not for a gather).
  RoundGridMaps(const std::vector<engine::ReceiverPlane>& planes, const std::vector<int>& plane_of_grid, bool gather,
                engine::TracedPhotons photons, std::vector<double> scale);
  ~RoundGridMaps();
  RoundGridMaps(const RoundGridMaps&) = delete;
  RoundGridMaps& operator=(const RoundGridMaps&) = delete;

  /// Grid g's maps, built on first use (thread-safe: the first caller builds, the others wait).
  const engine::GridPhotons& of_grid(std::size_t g);
  /// Grid g's estimates are done: the maps and photons that no later grid reads are released.
  void done(std::size_t g);
  /// Whether the photons or map that grid g reads are still held (not yet released by done).
  bool holds(std::size_t g) const;

 private:
  std::size_t slot_of(std::size_t g) const;
  const std::vector<engine::ReceiverPlane>& m_planes;
  std::vector<int> m_plane_of_grid;
  bool m_gather = false;
  engine::TracedPhotons m_photons;
  std::vector<double> m_scale;
  struct Slot;  ///< a map built on first use (LazyValue)
  /// Per slot (each plane, then the surface photons): its map and the last grid that reads it.
  std::vector<std::unique_ptr<Slot>> m_maps;
  std::vector<std::size_t> m_last_grid;
};

}  // namespace dayphoton::study
