// The photon maps of one accuracy round's grids: see round_grid_maps.h.
#include "dayphoton/study/round_grid_maps.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "lazy_value.h"

namespace dayphoton::study {

struct RoundGridMaps::Slot {
  LazyValue<engine::GridPhotons> map;
};

RoundGridMaps::RoundGridMaps(const std::vector<engine::ReceiverPlane>& planes, const std::vector<int>& plane_of_grid,
                             bool gather, engine::TracedPhotons photons, std::vector<double> scale,
                             std::vector<std::size_t> near_cut_sensors)
    : m_planes(planes),
      m_plane_of_grid(plane_of_grid),
      m_gather(gather),
      m_photons(std::move(photons)),
      m_scale(std::move(scale)),
      m_near_cut_sensors(std::move(near_cut_sensors)) {
  m_near_cut_sensors.resize(planes.size(), 0);
  // Without a gathered grid the surface slot holds the surface estimate's map, so the planes'
  // sensors next to a cut get a gather map of their own, from a copy of the surface photons.
  bool near_cuts = false;
  for (std::size_t n : m_near_cut_sensors) near_cuts = near_cuts || n > 0;
  m_gather_slot = m_gather ? planes.size() : planes.size() + 1;
  if (near_cuts && !m_gather) m_gather_photons = m_photons.surface;
  const std::size_t slots = planes.size() + 2;
  if (m_photons.planes.size() < planes.size()) m_photons.planes.resize(planes.size());
  for (std::size_t s = 0; s < slots; ++s) m_maps.push_back(std::make_unique<Slot>());
  m_last_grid.assign(slots, 0);
  for (std::size_t g = 0; g < plane_of_grid.size(); ++g)
    for (std::size_t s : slots_of(g)) m_last_grid[s] = g;
}

RoundGridMaps::~RoundGridMaps() = default;

std::size_t RoundGridMaps::slot_of(std::size_t g) const {
  const int plane = m_plane_of_grid.at(g);
  if (plane >= int(m_planes.size()))
    throw std::out_of_range("RoundGridMaps: grid " + std::to_string(g) + " on plane " + std::to_string(plane) +
                            " of " + std::to_string(m_planes.size()));
  return plane >= 0 ? std::size_t(plane) : m_planes.size();
}

std::vector<std::size_t> RoundGridMaps::slots_of(std::size_t g) const {
  const std::size_t s = slot_of(g);
  if (s < m_planes.size() && m_near_cut_sensors[s] > 0) return {s, m_gather_slot};
  return {s};
}

const engine::GridPhotons& RoundGridMaps::slot_map(std::size_t s, std::size_t g, const engine::GridPhotons* near_cut_gather) {
  if (!m_maps[s]) throw std::logic_error("RoundGridMaps: grid " + std::to_string(g) + "'s photons were released");
  return m_maps[s]->map.get([&] {
    const std::size_t n = m_scale.size();
    // Moved in: this slot's photons are read by this map alone.
    if (s == m_planes.size() + 1) return engine::GridPhotons::for_gather(std::move(m_gather_photons), n);
    engine::GridPhotons gp =
        s < m_planes.size() ? engine::GridPhotons::for_plane(m_planes[s], std::move(m_photons.planes[s]), n)
        : m_gather          ? engine::GridPhotons::for_gather(std::move(m_photons.surface), n)
                            : engine::GridPhotons::for_surfaces(std::move(m_photons.surface), n);
    if (!gp.gather()) gp.set_source_scale(m_scale);
    // Not owned: the gather slot is released only after the last grid that reads it.
    if (near_cut_gather) gp.set_near_cut_gather(std::shared_ptr<const engine::GridPhotons>(std::shared_ptr<void>(), near_cut_gather));
    return gp;
  });
}

const engine::GridPhotons& RoundGridMaps::of_grid(std::size_t g) {
  const std::vector<std::size_t> slots = slots_of(g);
  if (slots.size() == 1) return slot_map(slots[0], g);
  // A plane with sensors next to a cut: the gather map first, then the plane's map reading it.
  const engine::GridPhotons& gather = slot_map(slots[1], g);
  return slot_map(slots[0], g, &gather);
}

void RoundGridMaps::done(std::size_t g) {
  for (std::size_t s : slots_of(g)) {
    if (m_last_grid[s] != g) continue;
    m_maps[s].reset();
    if (s < m_planes.size())
      std::vector<engine::Photon>().swap(m_photons.planes[s]);
    else if (s == m_planes.size())
      std::vector<engine::Photon>().swap(m_photons.surface);
    else
      std::vector<engine::Photon>().swap(m_gather_photons);
  }
}

bool RoundGridMaps::holds(std::size_t g) const {
  for (std::size_t s : slots_of(g))
    if (!m_maps[s]) return false;
  return true;
}

}  // namespace dayphoton::study
