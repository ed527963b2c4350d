// Deterministic photons for the receiver-plane estimate tests: one photon per 1 cm cell of
// the 4 x 4 m square [0, 4]^2 at z = 0.8, of flux E(x, y) x the cell's area, so a density
// estimate of them is a closed-form field up to the lattice's count error in a disc; and the
// coefficients' estimate those tests share.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/receiver_plane.h"

namespace dayphoton::engine::test {

/// The cells whose centre `plane` contains, each repeated for sources 0 .. sources - 1 (global
/// photons), on `plane` (its outline and cuts as given).
template <typename Field>
GridPhotons lattice_photons_on(const ReceiverPlane& plane, Field irradiance, std::size_t sources = 1) {
  std::vector<Photon> photons;
  const int n = 400;
  const double h = 4.0 / n;
  for (std::size_t source = 0; source < sources; ++source)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x = (i + 0.5) * h, y = (j + 0.5) * h;
        if (!plane.contains(x, y)) continue;
        Photon p;
        p.position = {float(x), float(y), 0.8f};
        const float f = static_cast<float>(irradiance(x, y) * h * h);
        p.flux = {f, f, f};
        p.source = static_cast<std::uint32_t>(source);
        p.path_class = PathClass::Global;
        p.set_normal({0, 0, 1});
        photons.push_back(p);
      }
  return GridPhotons::for_plane(plane, photons, sources);
}

/// The photon coefficients of `grid` at `sensors` for `sources` sources by `options`, sized
/// here (caustic and global zero before the estimate; with `keep_variance` the photon variance
/// too).
inline DaylightCoefficients estimate_coefficients(const GridPhotons& grid, const std::vector<SensorPoint>& sensors,
                                                const CoefficientOptions& options, std::size_t sources = 1,
                                                bool keep_variance = false) {
  DaylightCoefficients c;
  c.sensors = sensors.size();
  c.sources = sources;
  c.caustic.assign(sensors.size() * sources, Vec3{0, 0, 0});
  c.global.assign(sensors.size() * sources, Vec3{0, 0, 0});
  if (keep_variance) c.photon_variance.assign(sensors.size() * sources, 0.0);
  estimate_photon_coefficients(grid, sensors, options, c);
  return c;
}

}  // namespace dayphoton::engine::test
