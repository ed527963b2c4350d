// The photon part under a continuous sky: see photon_part_on_sky.h.
#include "dayphoton/engine/photon_part_on_sky.h"

#include <stdexcept>
#include <string>

#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/plane_cuts.h"

namespace dayphoton::engine {

PhotonOnSky photon_part_on_sky(const GridPhotons& photons, const std::vector<SensorPoint>& sensors,
                               const CoefficientOptions& options, const DaylightCoefficients& basis,
                               const std::vector<Vec3>& bin_radiance_rgb, SensorRange rows) {
  rows = rows.within(sensors.size());
  const std::size_t n = basis.sources, m = rows.size();
  if (basis.sensors != m || bin_radiance_rgb.size() != n || basis.caustic.size() != m * n ||
      basis.global.size() != m * n || basis.photon_variance.size() != m * n)
    throw std::invalid_argument("photon part on the sky: coefficients of " + std::to_string(basis.sensors) + " x " +
                                std::to_string(n) + " for " + std::to_string(m) + " rows and " +
                                std::to_string(bin_radiance_rgb.size()) + " bin radiances");
  std::vector<double> luminance(n);
  for (std::size_t p = 0; p < n; ++p) luminance[p] = luminance_of(bin_radiance_rgb[p]);

  // Which rows keep the basis sum: those a final gather estimates (header comment).
  std::vector<char> on_basis(m, photons.gather() ? 1 : 0);
  DaylightCoefficients weighted;
  if (!photons.gather()) {
    weighted.sensors = m;
    weighted.sources = n;
    weighted.caustic.assign(m * n, Vec3{0, 0, 0});
    weighted.global.assign(m * n, Vec3{0, 0, 0});
    CoefficientOptions o = options;
    o.density.flux = PhotonFlux::TimesSkyRatio;
    estimate_photon_coefficients(photons, sensors, o, weighted, rows);
    if (photons.near_cut_gather())
      for (const std::size_t s : sensors_near_cuts(*photons.plane(), sensors, rows)) on_basis[s - rows.begin] = 1;
  }

  PhotonOnSky out;
  out.irradiance.assign(m, Vec3{0, 0, 0});
  out.variance.assign(m, 0.0);
  for (std::size_t r = 0; r < m; ++r) {
    const DaylightCoefficients& c = on_basis[r] ? basis : weighted;
    Vec3 e{0, 0, 0};
    double v = 0;
    for (std::size_t p = 0; p < n; ++p) {
      const std::size_t i = r * n + p;
      e += mul(c.caustic[i] + c.global[i], bin_radiance_rgb[p]);
      v += luminance[p] * luminance[p] * c.photon_variance[i];
    }
    out.irradiance[r] = e;
    out.variance[r] = v;
    if (on_basis[r]) ++out.basis_rows;
  }
  return out;
}

}  // namespace dayphoton::engine
