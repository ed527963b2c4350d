// Sun bins: fixed sun positions that stand for every hourly sun of a year (issue 6 item 1;
// DESIGN.md section 5; seeds/001 section 4.3, where 365 daily suns were each their own
// contribution source). Each bin is a 0.533 degree sun disc at the centre of a patch of the
// Reinhart MF n subdivision (sky::PatchBasis::reinhart), traced with its own photons like a
// sky bin. The photon (caustic + global) coefficients of an hour's sun are interpolated from
// the bins; the direct sun is traced exactly per hour (study/annual_sun.h).
//
// Interpolation: bilinear on the Reinhart grid in (altitude, azimuth). The grid is a
// structured set of rows of equal height alpha = 90 / (7 n + 0.5) deg, row r centred on
// altitude (r + 1/2) alpha, with N_r patches of equal width centred on azimuths j 360/N_r
// (clockwise from north). For a sun at altitude h and azimuth phi:
//   - the two rows whose centre altitudes bracket h get weights (1 - t, t),
//     t = h / alpha - (r0 + 1/2); below the lowest row centre the lowest row takes all
//     (no extrapolation toward the horizon); above the highest row centre the second
//     "row" is the zenith cap (one patch, centred on the zenith);
//   - in each row the two patches whose centre azimuths bracket phi get (1 - s, s),
//     s = phi N_r / 360 - j0 (wrapping at north); the cap takes its row's whole weight.
// So a sun maps to at most 4 bins with non-negative weights summing to 1, the
// interpolation is exact for any function linear in (altitude, azimuth) over a cell, its
// error is second order in the patch spacing (about 2 deg for MF 6: rows 2.12 deg high,
// patches 2-10 deg wide), and it is continuous in the sun position. Barycentric weights
// over a spherical triangulation would be as accurate but need a triangulation of the
// chosen bins; inverse-distance weights are only first order and have flat spots at the
// bin centres.
//
// Choice of bins: exactly the patches that the stencils of the given hourly suns use. Every
// patch the sun visits is in its own stencil (the bracketing rows include the sun's row, the
// bracketing azimuths its patch), so the bins are the visited patches plus the neighbours
// their stencils reach across the analemma of each hour. Nothing else is traced.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::engine {

/// Up to 4 (index, weight) pairs, weights > 0 summing to 1.
struct SunStencil {
  int count = 0;
  std::array<int, 4> index{};     ///< patch numbers (patch_stencil) or sun-bin indices (SunBins)
  std::array<double, 4> weight{};
};

/// The bilinear stencil of `sun` (toward the sun, non-zero, z > 0) in patch numbers of
/// `basis` (1 .. bin_count - 1; never the ground bin 0). Entries with zero weight are
/// dropped, and a patch appears at most once. Throws std::invalid_argument for a direction
/// that is zero, not finite or not above the horizon.
SunStencil patch_stencil(const sky::PatchBasis& basis, const Vec3& sun);

class SunBins {
 public:
  /// The bins for these hourly suns (each toward the sun, above the horizon) on Reinhart MF
  /// `mf`: every patch some sun's stencil uses, in increasing patch order. Throws
  /// std::invalid_argument for a bad mf (see PatchBasis::reinhart) or a bad direction.
  static SunBins for_suns(const std::vector<Vec3>& suns, int mf);

  /// The bins of these patches of Reinhart MF `mf`, in this order (a set written out by an
  /// earlier run: sun_bins.csv). Throws std::invalid_argument for a bad mf, a patch outside
  /// 1 .. bin_count - 1, or a patch given twice.
  static SunBins from_patches(const std::vector<int>& patches, int mf);

  int multiplication_factor() const { return m_basis.multiplication_factor(); }
  const sky::PatchBasis& basis() const { return m_basis; }
  std::size_t size() const { return m_patch.size(); }
  /// Patch number in basis() of bin i, and its centre direction (unit, toward the sun).
  int patch(std::size_t i) const { return m_patch.at(i); }
  Vec3 direction(std::size_t i) const { return m_basis.centre(patch(i)); }
  /// Sun discs of the given angular radius at the bin centres: source i = bin i.
  SourceSet sources(double half_angle_rad) const;

  /// Interpolation weights of a sun over the bins (indices into this set). Throws
  /// std::out_of_range if the stencil needs a patch that is not a bin (a sun that was not
  /// among those the bins were chosen for and lies outside their cells).
  SunStencil weights(const Vec3& sun) const;

 private:
  explicit SunBins(int mf);
  sky::PatchBasis m_basis;
  std::vector<int> m_patch;            ///< per bin: patch number
  std::vector<int> m_bin_of_patch;     ///< per patch: bin index, -1 if not a bin
};

}  // namespace dayphoton::engine
