// Sun bins and their bilinear (altitude, azimuth) interpolation on the Reinhart grid; the
// choice and the stencil are explained in engine/include/dayphoton/engine/sun_bins.h.
#include "dayphoton/engine/sun_bins.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

void add(SunStencil& s, int index, double weight) {
  if (!(weight > 0.0)) return;
  for (int k = 0; k < s.count; ++k)
    if (s.index[static_cast<std::size_t>(k)] == index) {
      s.weight[static_cast<std::size_t>(k)] += weight;
      return;
    }
  s.index[static_cast<std::size_t>(s.count)] = index;
  s.weight[static_cast<std::size_t>(s.count)] = weight;
  ++s.count;
}

/// Spread `weight` over the two patches of row `r` whose centre azimuths bracket the sun's
/// (the cap, a row of one patch, takes it all).
void add_row(const sky::PatchBasis& basis, int r, double azimuth_rad, double weight, SunStencil& s) {
  if (!(weight > 0.0)) return;
  const sky::PatchRow& row = basis.row(r);
  const int n = row.patch_count;
  if (n == 1) {
    add(s, row.first_bin, weight);
    return;
  }
  const double x = azimuth_rad / (2.0 * Pi) * n;  // in patch widths from north's centre
  double j0 = std::floor(x);
  double f = x - j0;
  if (f >= 1.0) f = 0.0, j0 += 1.0;  // rounding at the top of a cell
  const int a = static_cast<int>(j0) % n;
  const int b = (a + 1) % n;
  add(s, row.first_bin + a, weight * (1.0 - f));
  add(s, row.first_bin + b, weight * f);
}

}  // namespace

SunStencil patch_stencil(const sky::PatchBasis& basis, const Vec3& sun) {
  const double len = length(sun);
  if (!is_finite(sun) || !(len > 0.0) || !(sun.z > 0.0))
    throw std::invalid_argument("sun bins: a sun direction must be finite and above the horizon");
  const double altitude = std::asin(std::clamp(sun.z / len, -1.0, 1.0));
  double azimuth = std::atan2(sun.x, sun.y);  // clockwise from north (+Y) toward east (+X)
  if (azimuth < 0.0) azimuth += 2.0 * Pi;
  if (azimuth >= 2.0 * Pi) azimuth = 0.0;

  // Row r (the cap is row 7 mf) is centred on altitude (r + 1/2) alpha: the cap's centre,
  // the zenith, is (7 mf + 1/2) alpha = 90 deg, so one formula covers every row.
  const int cap = basis.row_count() - 1;
  const double x = altitude / basis.row_height_rad() - 0.5;
  SunStencil s;
  if (x <= 0.0) {
    add_row(basis, 0, azimuth, 1.0, s);  // below the lowest centres: that row alone
  } else if (x >= cap) {
    add_row(basis, cap, azimuth, 1.0, s);
  } else {
    const int r0 = static_cast<int>(std::floor(x));
    const double t = x - r0;
    add_row(basis, r0, azimuth, 1.0 - t, s);
    add_row(basis, std::min(r0 + 1, cap), azimuth, t, s);
  }
  return s;
}

SunBins::SunBins(int mf) : m_basis(sky::PatchBasis::reinhart(mf)) {
  m_bin_of_patch.assign(static_cast<std::size_t>(m_basis.bin_count()), -1);
}

SunBins SunBins::for_suns(const std::vector<Vec3>& suns, int mf) {
  SunBins bins(mf);
  std::vector<char> used(static_cast<std::size_t>(bins.m_basis.bin_count()), 0);
  for (const Vec3& sun : suns) {
    const SunStencil s = patch_stencil(bins.m_basis, sun);
    for (int k = 0; k < s.count; ++k) used[static_cast<std::size_t>(s.index[static_cast<std::size_t>(k)])] = 1;
  }
  for (int patch = 1; patch < bins.m_basis.bin_count(); ++patch) {
    if (!used[static_cast<std::size_t>(patch)]) continue;
    bins.m_bin_of_patch[static_cast<std::size_t>(patch)] = static_cast<int>(bins.m_patch.size());
    bins.m_patch.push_back(patch);
  }
  return bins;
}

SunBins SunBins::from_patches(const std::vector<int>& patches, int mf) {
  SunBins bins(mf);
  for (const int patch : patches) {
    if (patch < 1 || patch >= bins.m_basis.bin_count())
      throw std::invalid_argument("sun bins: patch " + std::to_string(patch) + " is not a sky patch of Reinhart MF " +
                                  std::to_string(mf) + " (1.." + std::to_string(bins.m_basis.bin_count() - 1) + ")");
    int& bin = bins.m_bin_of_patch[static_cast<std::size_t>(patch)];
    if (bin >= 0) throw std::invalid_argument("sun bins: patch " + std::to_string(patch) + " given twice");
    bin = static_cast<int>(bins.m_patch.size());
    bins.m_patch.push_back(patch);
  }
  return bins;
}

SourceSet SunBins::sources(double half_angle_rad) const {
  SourceSet set;
  for (int patch : m_patch) set.add_sun_disc(m_basis.centre(patch), half_angle_rad);
  return set;
}

SunStencil SunBins::weights(const Vec3& sun) const {
  SunStencil s = patch_stencil(m_basis, sun);
  for (int k = 0; k < s.count; ++k) {
    int& index = s.index[static_cast<std::size_t>(k)];
    const int bin = m_bin_of_patch[static_cast<std::size_t>(index)];
    if (bin < 0)
      throw std::out_of_range("sun bins: the sun needs patch " + std::to_string(index) +
                              ", which is not a sun bin");
    index = bin;
  }
  return s;
}

}  // namespace dayphoton::engine
