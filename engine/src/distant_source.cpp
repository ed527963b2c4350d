// SourceSet: sky bins of a patch basis and sun discs as distant sources of unit radiance.
// Sampling maps and their sources are given in engine/include/dayphoton/engine/distant_source.h.
#include "dayphoton/engine/distant_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {
namespace {

/// 1 - cos(a) without cancellation for small a.
double one_minus_cos(double a_rad) {
  const double s = std::sin(0.5 * a_rad);
  return 2.0 * s * s;
}

/// Two unit vectors completing the unit vector n to a right-handed orthonormal frame
/// (Duff, Burgess, Christensen, Hery, Kensler, Liani & Villemin, "Building an orthonormal
/// basis, revisited", JCGT 6(1), 2017, listing 3: branch-free and continuous except at the
/// sign flip of n.z).
void orthonormal_frame(const Vec3& n, Vec3& t1, Vec3& t2) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  t1 = Vec3{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  t2 = Vec3{b, sign + n.y * n.y * a, -n.y};
}

}  // namespace

SourceSet SourceSet::sky_bins(const sky::PatchBasis& basis) {
  SourceSet set;
  set.m_basis = basis;
  set.m_has_basis = true;
  set.m_sources.reserve(static_cast<std::size_t>(basis.bin_count()));
  for (int bin = 0; bin < basis.bin_count(); ++bin) {
    DistantSource s;
    s.kind = SourceKind::SkyBin;
    s.bin = bin;
    s.direction = basis.centre(bin);
    s.solid_angle_sr = basis.solid_angle_sr(bin);
    set.m_sources.push_back(s);
  }
  return set;
}

std::size_t SourceSet::add_sun_disc(const Vec3& direction, double half_angle_rad) {
  const double len = length(direction);
  if (!is_finite(direction) || !(len > 0.0))
    throw std::invalid_argument("sun disc: the direction must be finite and non-zero");
  if (!(half_angle_rad > 0.0 && half_angle_rad <= Pi))
    throw std::invalid_argument("sun disc: angular radius " + std::to_string(half_angle_rad) +
                                " rad must lie in (0, pi]");
  DistantSource s;
  s.kind = SourceKind::SunDisc;
  s.bin = -1;
  s.direction = direction / len;
  s.half_angle_rad = half_angle_rad;
  s.solid_angle_sr = 2.0 * Pi * one_minus_cos(half_angle_rad);
  m_sources.push_back(s);
  return m_sources.size() - 1;
}

Vec3 SourceSet::sample_direction(std::size_t i, double u1, double u2) const {
  const DistantSource& s = m_sources.at(i);
  if (s.kind == SourceKind::SkyBin) return m_basis.sample_direction(s.bin, u1, u2);

  // Uniform in the cone: 1 - cos(theta) = u1 (1 - cos a) is uniform, and
  // sin^2(theta) = (1 - cos theta)(1 + cos theta) keeps precision near the centre.
  const double one_minus_cos_theta = u1 * one_minus_cos(s.half_angle_rad);
  const double cos_theta = 1.0 - one_minus_cos_theta;
  const double sin_theta =
      std::sqrt(std::max(0.0, one_minus_cos_theta * (2.0 - one_minus_cos_theta)));
  const double phi = 2.0 * Pi * u2;
  Vec3 t1, t2;
  orthonormal_frame(s.direction, t1, t2);
  return normalize(t1 * (sin_theta * std::cos(phi)) + t2 * (sin_theta * std::sin(phi)) +
                   s.direction * cos_theta);
}

bool SourceSet::contains(std::size_t i, const Vec3& direction) const {
  const DistantSource& s = m_sources.at(i);
  if (s.kind == SourceKind::SkyBin) return m_basis.find_bin(direction) == s.bin;
  // 1 - cos(angle) = |d - c|^2 / 2 for unit d, c: no cancellation near the centre, where a
  // 0.27 degree sun lives (1 - cos a = 1.1e-5).
  const Vec3 chord = normalize(direction) - s.direction;
  return 0.5 * dot(chord, chord) <= one_minus_cos(s.half_angle_rad);
}

int SourceSet::find(const Vec3& direction) const {
  if (m_has_basis) {
    // sky_bins puts bin i at index i; sun discs may follow.
    const int bin = m_basis.find_bin(direction);
    if (bin >= 0 && static_cast<std::size_t>(bin) < m_sources.size() &&
        m_sources[static_cast<std::size_t>(bin)].kind == SourceKind::SkyBin && m_sources[static_cast<std::size_t>(bin)].bin == bin)
      return bin;
  }
  for (std::size_t i = 0; i < m_sources.size(); ++i)
    if (m_sources[i].kind == SourceKind::SunDisc && contains(i, direction)) return static_cast<int>(i);
  return -1;
}

}  // namespace dayphoton::engine
