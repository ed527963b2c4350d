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
                             bool gather, engine::TracedPhotons photons, std::vector<double> scale)
    : m_planes(planes),
      m_plane_of_grid(plane_of_grid),
      m_gather(gather),
      m_photons(std::move(photons)),
      m_scale(std::move(scale)) {
  const std::size_t slots = planes.size() + 1;
  if (m_photons.planes.size() < planes.size()) m_photons.planes.resize(planes.size());
  for (std::size_t s = 0; s < slots; ++s) m_maps.push_back(std::make_unique<Slot>());
  m_last_grid.assign(slots, 0);
  for (std::size_t g = 0; g < plane_of_grid.size(); ++g) m_last_grid[slot_of(g)] = g;
}

RoundGridMaps::~RoundGridMaps() = default;

std::size_t RoundGridMaps::slot_of(std::size_t g) const {
  const int plane = m_plane_of_grid.at(g);
  if (plane >= int(m_planes.size()))
    throw std::out_of_range("RoundGridMaps: grid " + std::to_string(g) + " on plane " + std::to_string(plane) +
                            " of " + std::to_string(m_planes.size()));
  return plane >= 0 ? std::size_t(plane) : m_planes.size();
}

const engine::GridPhotons& RoundGridMaps::of_grid(std::size_t g) {
  const std::size_t s = slot_of(g);
  if (!m_maps[s]) throw std::logic_error("RoundGridMaps: grid " + std::to_string(g) + "'s photons were released");
  return m_maps[s]->map.get([&] {
    const std::size_t n = m_scale.size();
    // Moved in: this slot's photons are read by this map alone.
    engine::GridPhotons gp =
        s < m_planes.size() ? engine::GridPhotons::for_plane(m_planes[s], std::move(m_photons.planes[s]), n)
        : m_gather          ? engine::GridPhotons::for_gather(std::move(m_photons.surface), n)
                            : engine::GridPhotons::for_surfaces(std::move(m_photons.surface), n);
    if (!gp.gather()) gp.set_source_scale(m_scale);
    return gp;
  });
}

void RoundGridMaps::done(std::size_t g) {
  const std::size_t s = slot_of(g);
  if (m_last_grid[s] != g) return;
  m_maps[s].reset();
  if (s < m_planes.size())
    std::vector<engine::Photon>().swap(m_photons.planes[s]);
  else
    std::vector<engine::Photon>().swap(m_photons.surface);
}

bool RoundGridMaps::holds(std::size_t g) const { return m_maps[slot_of(g)] != nullptr; }

}  // namespace dayphoton::study
