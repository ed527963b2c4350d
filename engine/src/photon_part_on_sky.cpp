// The photon part under a continuous sky: see photon_part_on_sky.h.
#include "dayphoton/engine/photon_part_on_sky.h"

#include <stdexcept>
#include <string>

#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/plane_cuts.h"

namespace dayphoton::engine {
namespace {

/// Row r of `c`'s photon part summed with the bin radiances (`luminance`: theirs), and its
/// variance.
void reduce_row(const DaylightCoefficients& c, std::size_t r, const std::vector<Vec3>& bin_radiance_rgb,
                const std::vector<double>& luminance, Vec3& irradiance, double& variance) {
  Vec3 e{0, 0, 0};
  double v = 0;
  for (std::size_t p = 0; p < c.sources; ++p) {
    const std::size_t i = r * c.sources + p;
    e += mul(c.caustic[i] + c.global[i], bin_radiance_rgb[p]);
    v += luminance[p] * luminance[p] * c.photon_variance[i];
  }
  irradiance = e;
  variance = v;
}

std::vector<double> luminances(const std::vector<Vec3>& rgb) {
  std::vector<double> out(rgb.size());
  for (std::size_t p = 0; p < rgb.size(); ++p) out[p] = luminance_of(rgb[p]);
  return out;
}

}  // namespace

void set_basis_row(PhotonOnSky& on_sky, std::size_t row, const DaylightCoefficients& c, std::size_t from_row,
                   const std::vector<Vec3>& bin_radiance_rgb) {
  if (row >= on_sky.irradiance.size() || row >= on_sky.variance.size() || from_row >= c.sensors ||
      bin_radiance_rgb.size() != c.sources || c.caustic.size() < (from_row + 1) * c.sources ||
      c.global.size() < (from_row + 1) * c.sources || c.photon_variance.size() < (from_row + 1) * c.sources)
    throw std::out_of_range("photon part on the sky: row " + std::to_string(row) + " from row " +
                            std::to_string(from_row) + " of " + std::to_string(c.sensors));
  reduce_row(c, from_row, bin_radiance_rgb, luminances(bin_radiance_rgb), on_sky.irradiance[row], on_sky.variance[row]);
}

PhotonOnSky photon_part_on_sky_of(const GridPhotons& photons, const std::vector<SensorPoint>& sensors,
                                  const DaylightCoefficients& basis, const DaylightCoefficients* weighted,
                                  const std::vector<Vec3>& bin_radiance_rgb, SensorRange rows,
                                  const GatheredCoefficients* gathered) {
  rows = rows.within(sensors.size());
  const std::size_t n = basis.sources, m = rows.size();
  auto holds = [&](const DaylightCoefficients& c) {
    return c.sensors == m && c.sources == n && c.caustic.size() == m * n && c.global.size() == m * n &&
           c.photon_variance.size() == m * n;
  };
  if (!holds(basis) || bin_radiance_rgb.size() != n || (weighted && !holds(*weighted)) ||
      (!weighted && !photons.gather()))
    throw std::invalid_argument("photon part on the sky: coefficients of " + std::to_string(basis.sensors) + " x " +
                                std::to_string(n) + " for " + std::to_string(m) + " rows and " +
                                std::to_string(bin_radiance_rgb.size()) + " bin radiances" +
                                (weighted ? "" : ", and no ratio-weighted estimate"));
  const std::vector<double> luminance = luminances(bin_radiance_rgb);
  // The rows a final gather estimates, in the gather's order (header comment).
  std::vector<std::size_t> gathered_rows;
  if (photons.gather()) {
    gathered_rows.resize(m);
    for (std::size_t r = 0; r < m; ++r) gathered_rows[r] = r;
  } else if (photons.near_cut_gather()) {
    for (const std::size_t s : sensors_near_cuts(*photons.plane(), sensors, rows)) gathered_rows.push_back(s - rows.begin);
  }
  const bool gather_on_sky = gathered && !gathered->on_sky.empty();
  if (gather_on_sky &&
      (gathered->on_sky.size() != gathered_rows.size() || gathered->on_sky_variance.size() != gathered_rows.size()))
    throw std::invalid_argument("photon part on the sky: the gather's estimate on the sky has " +
                                std::to_string(gathered->on_sky.size()) + " rows and " +
                                std::to_string(gathered->on_sky_variance.size()) + " variances for " +
                                std::to_string(gathered_rows.size()) + " gathered rows");
  std::vector<char> by_gather(m, 0);
  for (const std::size_t r : gathered_rows) by_gather[r] = 1;
  PhotonOnSky out;
  out.irradiance.assign(m, Vec3{0, 0, 0});
  out.variance.assign(m, 0.0);
  for (std::size_t r = 0; r < m; ++r)
    if (!by_gather[r]) reduce_row(*weighted, r, bin_radiance_rgb, luminance, out.irradiance[r], out.variance[r]);
  for (std::size_t i = 0; i < gathered_rows.size(); ++i) {
    const std::size_t r = gathered_rows[i];
    if (gather_on_sky) {
      out.irradiance[r] = gathered->on_sky[i];
      out.variance[r] = gathered->on_sky_variance[i];
    } else {
      reduce_row(basis, r, bin_radiance_rgb, luminance, out.irradiance[r], out.variance[r]);
      ++out.basis_rows;
    }
  }
  return out;
}

}  // namespace dayphoton::engine
