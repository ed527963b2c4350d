// RoundGridMaps: the photon maps of one accuracy round's grids, made from the round's photons
// (round_photons) without copying them. Every grid that reads the surface photons (a final
// gather, or sensors on surfaces: the same for every such grid of a case) shares one map, and
// each receiver plane's photons make the map of the grid on that plane; the photons are moved
// into the map that reads them, which is built on first use (LazyValue: only in a process that
// estimates some block of a grid that reads it) and released after the last grid that reads it
// (done). A round then holds its records and one scaled copy of their photons, in the maps,
// where each grid used to copy the surface photons into a map of its own (29 M photons, 0.9 GB
// a copy, on projects/honeybee at the default accuracy: docs/photon-tracing.md "Scale").
// A plane with sensors next to a cut (study::CaseLayout::near_cut_sensors) reads the gather map
// too, for those sensors' final gather (engine::GridPhotons::set_near_cut_gather): the gathered
// grids' shared map, or, when the other grids read the surface estimate's, one of its own from a
// copy of the surface photons. The accuracy rounds ask for it only when a gathered grid builds
// that map anyway (accuracy_policy.h, near_cut_gathered_in_rounds).
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
  /// count relative to the reference (GridPhotons::set_source_scale, not for a gather);
  /// `near_cut_sensors`: per plane, its sensors next to a cut (CaseLayout::near_cut_sensors;
  /// empty: none), whose plane then reads the gather map too.
  RoundGridMaps(const std::vector<engine::ReceiverPlane>& planes, const std::vector<int>& plane_of_grid, bool gather,
                engine::TracedPhotons photons, std::vector<double> scale,
                std::vector<std::size_t> near_cut_sensors = {});
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
  /// The slots grid g reads: its own, and the gather slot for a plane with sensors next to a cut.
  std::vector<std::size_t> slots_of(std::size_t g) const;
  /// Slot s's map, built on first use (for grid g); a plane's reads `near_cut_gather`.
  const engine::GridPhotons& slot_map(std::size_t s, std::size_t g, const engine::GridPhotons* near_cut_gather = nullptr);
  const std::vector<engine::ReceiverPlane>& m_planes;
  std::vector<int> m_plane_of_grid;
  bool m_gather = false;
  engine::TracedPhotons m_photons;
  std::vector<double> m_scale;
  std::vector<std::size_t> m_near_cut_sensors;  ///< per plane
  std::size_t m_gather_slot = 0;  ///< the surface slot when `gather`, else the one after it
  std::vector<engine::Photon> m_gather_photons;  ///< that slot's copy of the surface photons
  struct Slot;  ///< a map built on first use (LazyValue)
  /// Per slot (each plane, the surface photons, the planes' own gather map): its map and the
  /// last grid that reads it.
  std::vector<std::unique_ptr<Slot>> m_maps;
  std::vector<std::size_t> m_last_grid;
};

}  // namespace dayphoton::study
