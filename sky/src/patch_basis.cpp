// Tregenza / Reinhart sky patch bases in RADIANCE order (ground bin 0, rows from the
// horizon up, each row starting with the patch centred on north and going toward east,
// zenith cap last).
// Sources: ../shared/facts/sky-and-metrics.md sections 4.1-4.2, restating RADIANCE
// src/cal/cal/tregenza.cal, reinhart.cal and gendaymtx.c rh_init (formulas only).
// Solid angles: band 2 pi (sin h_top - sin h_bottom) / n; cap 2 pi (1 - cos(alpha/2)).
#include "dayphoton/sky/patch_basis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

// Patches per Tregenza band, the pattern Reinhart rows repeat MF times (facts 4.2).
constexpr int TregenzaBandPatches[7] = {30, 30, 24, 24, 18, 12, 6};
constexpr int MaxMultiplicationFactor = 64;

}  // namespace

PatchBasis PatchBasis::tregenza() { return PatchBasis(1); }

PatchBasis PatchBasis::reinhart(int mf) {
  if (mf < 1 || mf > MaxMultiplicationFactor)
    throw std::invalid_argument("Reinhart sky subdivision: multiplication factor " +
                                std::to_string(mf) + " must lie in 1.." +
                                std::to_string(MaxMultiplicationFactor));
  return PatchBasis(mf);
}

PatchBasis::PatchBasis(int mf) : m_mf(mf) {
  m_row_height_deg = 90.0 / (7.0 * mf + 0.5);
  m_row_height_rad = deg_to_rad(m_row_height_deg);
  const int sky_rows = 7 * mf;
  int next_bin = 1;
  m_bin_row.push_back(-1);  // ground
  for (int r = 0; r < sky_rows; ++r) {
    PatchRow row;
    row.altitude_min_rad = deg_to_rad(r * m_row_height_deg);
    row.altitude_max_rad = deg_to_rad((r + 1) * m_row_height_deg);
    row.patch_count = mf * TregenzaBandPatches[r / mf];
    row.first_bin = next_bin;
    next_bin += row.patch_count;
    m_bin_row.insert(m_bin_row.end(), static_cast<std::size_t>(row.patch_count), r);
    m_rows.push_back(row);
  }
  PatchRow cap;
  cap.altitude_min_rad = deg_to_rad(sky_rows * m_row_height_deg);
  cap.altitude_max_rad = Pi / 2.0;
  cap.patch_count = 1;
  cap.first_bin = next_bin++;
  m_bin_row.push_back(sky_rows);
  m_rows.push_back(cap);
  m_bin_count = next_bin;
  for (int bin = 0; bin < m_bin_count; ++bin) {
    const PatchBounds b = bounds(bin);
    m_sampling.push_back({b, std::sin(b.altitude_min_rad), std::sin(b.altitude_max_rad)});
    m_centres.push_back(compute_centre(bin));
  }
}

void PatchBasis::check_bin(int bin) const {
  if (bin < 0 || bin >= m_bin_count)
    throw std::out_of_range("sky patch bin " + std::to_string(bin) + " outside 0.." +
                            std::to_string(m_bin_count - 1));
}

int PatchBasis::row_of_bin(int bin) const {
  check_bin(bin);
  return m_bin_row[static_cast<std::size_t>(bin)];
}

int PatchBasis::find_bin(const Vec3& d) const {
  const double len = length(d);
  if (!(len > 0.0)) return 0;
  // Same arithmetic as the cal files: degrees, clamped asin, atan2 mapped to [0, 360).
  constexpr double degree = Pi / 180.0;
  const double sz = std::clamp(d.z / len, -1.0, 1.0);
  const double alt = std::asin(sz) / degree;
  if (alt < 0.0) return 0;
  double azi_rad = std::atan2(d.x, d.y);
  if (azi_rad < 0.0) azi_rad += 2.0 * Pi;
  const double azi = azi_rad / degree;
  const int r = static_cast<int>(std::floor(alt / m_row_height_deg));
  if (r >= 7 * m_mf) return m_rows.back().first_bin;
  const PatchRow& row = m_rows[static_cast<std::size_t>(r)];
  const double inc = 360.0 / row.patch_count;
  const int j = (359.9999 - 0.5 * inc - azi > 0.0)
                    ? static_cast<int>(std::floor((azi + 0.5 * inc) / inc))
                    : 0;
  return row.first_bin + j;
}

double PatchBasis::solid_angle_sr(int bin) const {
  check_bin(bin);
  if (bin == 0) return 2.0 * Pi;
  const PatchRow& row = m_rows[static_cast<std::size_t>(m_bin_row[static_cast<std::size_t>(bin)])];
  return 2.0 * Pi * (std::sin(row.altitude_max_rad) - std::sin(row.altitude_min_rad)) /
         row.patch_count;
}

PatchBounds PatchBasis::bounds(int bin) const {
  check_bin(bin);
  PatchBounds b;
  if (bin == 0) {
    b.altitude_min_rad = -Pi / 2.0;
    b.altitude_max_rad = 0.0;
    b.azimuth_min_rad = 0.0;
    b.azimuth_max_rad = 2.0 * Pi;
    return b;
  }
  const PatchRow& row = m_rows[static_cast<std::size_t>(m_bin_row[static_cast<std::size_t>(bin)])];
  b.altitude_min_rad = row.altitude_min_rad;
  b.altitude_max_rad = row.altitude_max_rad;
  if (row.patch_count == 1) {
    b.azimuth_min_rad = 0.0;
    b.azimuth_max_rad = 2.0 * Pi;
    return b;
  }
  const double w = 2.0 * Pi / row.patch_count;
  const double c = (bin - row.first_bin) * w;
  b.azimuth_min_rad = c - 0.5 * w;
  b.azimuth_max_rad = c + 0.5 * w;
  return b;
}

Vec3 PatchBasis::centre(int bin) const {
  check_bin(bin);
  return m_centres[static_cast<std::size_t>(bin)];
}

Vec3 PatchBasis::compute_centre(int bin) const {
  if (bin == 0) return Vec3{0.0, 0.0, -1.0};
  const int r = m_bin_row[static_cast<std::size_t>(bin)];
  const PatchRow& row = m_rows[static_cast<std::size_t>(r)];
  if (row.patch_count == 1) return Vec3{0.0, 0.0, 1.0};
  const double alt = deg_to_rad((r + 0.5) * m_row_height_deg);
  const double az = (bin - row.first_bin) * 2.0 * Pi / row.patch_count;
  return Vec3{std::cos(alt) * std::sin(az), std::cos(alt) * std::cos(az), std::sin(alt)};
}

Vec3 PatchBasis::sample_direction(int bin, double u1, double u2) const {
  check_bin(bin);
  const SamplingBounds& s = m_sampling[static_cast<std::size_t>(bin)];
  const PatchBounds& b = s.bounds;
  const double z0 = s.sin_altitude_min, z1 = s.sin_altitude_max;
  const double z = z0 + u1 * (z1 - z0);
  const double az = b.azimuth_min_rad + u2 * (b.azimuth_max_rad - b.azimuth_min_rad);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return Vec3{r * std::sin(az), r * std::cos(az), z};
}

int PatchBasis::quadrant(int bin, const Vec3& direction) const {
  check_bin(bin);
  if (bin == 0) return 0;
  const SamplingBounds& s = m_sampling[static_cast<std::size_t>(bin)];
  const double len = length(direction);
  const bool upper = direction.z / len >= 0.5 * (s.sin_altitude_min + s.sin_altitude_max);
  // Azimuth clockwise from north, measured from the bin's lower edge (the north patch of a
  // row starts below 0).
  double from_edge = std::atan2(direction.x, direction.y) - s.bounds.azimuth_min_rad;
  from_edge -= 2.0 * Pi * std::floor(from_edge / (2.0 * Pi));
  const bool later = from_edge >= 0.5 * (s.bounds.azimuth_max_rad - s.bounds.azimuth_min_rad);
  return 2 * static_cast<int>(upper) + static_cast<int>(later);
}

}  // namespace dayphoton::sky
