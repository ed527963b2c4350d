// PatchBasis: the Tregenza (145) and Reinhart MF n (144 n^2 + 1) sky subdivisions with
// RADIANCE's ground bin 0, in RADIANCE row order (the row order of gendaymtx sky matrices
// and of rcontrib/rfluxmtx coefficient columns).
//
// Sources: Tregenza 1987 (Lighting Res. Technol. 19(1) 13-14); Reinhart's subdivision as
// RADIANCE implements it in src/cal/cal/tregenza.cal, reinhart.cal and gendaymtx.c rh_init,
// restated in ../shared/facts/sky-and-metrics.md section 4.1-4.2 (no code copied).
//
// Layout (all angles as RADIANCE: altitude above the horizon, azimuth clockwise from north
// = +Y toward east = +X):
//   - bin 0: the ground, every direction with altitude < 0; solid angle 2 pi.
//   - sky rows r = 0 .. 7 MF - 1 of height alpha = 90 / (7 MF + 0.5) deg cover altitudes
//     [r alpha, (r+1) alpha); row r has MF * {30,30,24,24,18,12,6}[floor(r / MF)] patches of
//     width 360/n deg, patch j centred on azimuth j * 360/n (patch 0 of a row centred on
//     north, then toward EAST) and spanning [centre - w/2, centre + w/2).
//   - the zenith cap, altitudes [90 - alpha/2, 90], is the last bin (145 for Tregenza).
// find_bin reproduces the cal files' arithmetic exactly (degrees, floor, and the cal files'
// 359.9999 deg wrap test), so a direction lands in the same bin as in rcontrib.
#pragma once

#include <vector>

#include "dayphoton/core/vec3.h"

namespace dayphoton::sky {

/// One altitude row of the basis (the zenith cap is a row of one patch).
struct PatchRow {
  double altitude_min_rad = 0.0;
  double altitude_max_rad = 0.0;
  int patch_count = 0;  ///< patches in this row
  int first_bin = 0;    ///< bin index of the patch centred on north
};

/// Angular extent of one bin. Azimuths clockwise from north; the north patch of a row has
/// azimuth_min_rad < 0. The ground bin spans altitude [-pi/2, 0), the cap azimuth [0, 2 pi).
struct PatchBounds {
  double altitude_min_rad = 0.0;
  double altitude_max_rad = 0.0;
  double azimuth_min_rad = 0.0;
  double azimuth_max_rad = 0.0;
};

class PatchBasis {
 public:
  /// Tregenza 145 sky patches + ground (identical to reinhart(1)).
  static PatchBasis tregenza();
  /// Reinhart subdivision with multiplication factor mf (1..64); throws
  /// std::invalid_argument otherwise.
  static PatchBasis reinhart(int mf);

  int multiplication_factor() const { return m_mf; }
  /// Number of bins including the ground bin 0: 144 mf^2 + 2.
  int bin_count() const { return m_bin_count; }
  /// Sky rows including the zenith cap (7 mf + 1).
  int row_count() const { return static_cast<int>(m_rows.size()); }
  const PatchRow& row(int r) const { return m_rows.at(static_cast<std::size_t>(r)); }
  /// Row of a sky bin; -1 for the ground bin 0. Throws std::out_of_range for a bad bin.
  int row_of_bin(int bin) const;
  /// Height of a sky row, alpha = 90 / (7 mf + 0.5) degrees, in radians.
  double row_height_rad() const { return m_row_height_rad; }

  /// Bin of a direction (need not be unit length, must be non-zero): 0 when below the
  /// horizon (z < 0), the RADIANCE cal files' rule otherwise.
  int find_bin(const Vec3& direction) const;

  double solid_angle_sr(int bin) const;
  /// Patch centre direction as gendaymtx uses it: altitude (r + 0.5) alpha, azimuth j w;
  /// the zenith for the cap; straight down for the ground.
  Vec3 centre(int bin) const;
  PatchBounds bounds(int bin) const;

  /// Direction uniformly distributed in solid angle within the bin from u1, u2 in [0, 1)
  /// (u1 -> sin altitude, u2 -> azimuth). pdf = 1 / solid_angle_sr(bin) per steradian.
  Vec3 sample_direction(int bin, double u1, double u2) const;
  double pdf_sr(int bin) const { return 1.0 / solid_angle_sr(bin); }

  /// Quadrants of a sky bin (the annual product's sub-patches, docs/direct-component.md
  /// "Continuous skies"): its halves in sine of altitude and in azimuth, four parts of equal
  /// solid angle; quadrant = 2 (upper half in sine of altitude) + (upper half in azimuth),
  /// which is 2 (u1 >= 1/2) + (u2 >= 1/2) of sample_direction's numbers. `direction` (non-zero)
  /// is taken to lie in the bin (find_bin); the ground bin's quadrant is 0.
  int quadrant(int bin, const Vec3& direction) const;
  /// The four quadrants of a bin.
  static constexpr int QuadrantCount = 4;

 private:
  explicit PatchBasis(int mf);
  void check_bin(int bin) const;

  int m_mf = 1;
  int m_bin_count = 0;
  double m_row_height_deg = 0.0;
  double m_row_height_rad = 0.0;
  std::vector<PatchRow> m_rows;
  std::vector<int> m_bin_row;  ///< row of each bin (-1 for ground)
  /// Per bin: bounds(bin) and the sines of its altitude limits, so that sample_direction (on
  /// every photon emission) needs no sine but the azimuth's.
  struct SamplingBounds {
    PatchBounds bounds;
    double sin_altitude_min = 0, sin_altitude_max = 0;
  };
  std::vector<SamplingBounds> m_sampling;
  /// Per bin: centre(bin), computed once (the sun spread looks at every centre for every sun).
  std::vector<Vec3> m_centres;
  Vec3 compute_centre(int bin) const;
};

}  // namespace dayphoton::sky
