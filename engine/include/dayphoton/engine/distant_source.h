// Distant sources: the sky bins (patches of a Tregenza/Reinhart basis, ground bin 0
// included) and sun discs, each of unit radiance over its solid angle (DESIGN.md section 5;
// seeds/000 section 4.1.2). A daylight coefficient is the response to one such source, so
// the sources are what a coefficient matrix has columns for: source i = column i.
//
// Directions here point FROM the scene TOWARD the source (as sky directions do); light
// from the source propagates along the negated direction.
//
// Sampling (engine/src/distant_source.cpp):
//   - a sky bin delegates to sky::PatchBasis::sample_direction: u1 -> sin(altitude) linearly
//     between the bin's bounds, u2 -> azimuth linearly, which is uniform in solid angle
//     (Archimedes' hat-box theorem: dOmega = d(sin altitude) d(azimuth)). For the ground
//     bin 0 this is z = -1 + u1 over the whole lower hemisphere, azimuth 2 pi u2;
//   - a sun disc of angular radius a samples its cone uniformly in solid angle:
//     cos(theta) = 1 - u1 (1 - cos a), phi = 2 pi u2 about the disc centre, in an
//     orthonormal frame built with Duff et al., "Building an orthonormal basis, revisited",
//     JCGT 6(1), 2017. 1 - cos a is computed as 2 sin^2(a/2) so that a 0.27 degree sun keeps
//     full precision.
// Both maps are area preserving, so stratifying (u1, u2) stratifies the solid angle.
#pragma once

#include <cstddef>
#include <vector>

#include "dayphoton/core/vec3.h"
#include "dayphoton/sky/patch_basis.h"

namespace dayphoton::engine {

enum class SourceKind { SkyBin, SunDisc };

struct DistantSource {
  SourceKind kind = SourceKind::SkyBin;
  int bin = 0;                ///< SkyBin: bin of the basis (0 = ground); SunDisc: -1
  Vec3 direction;             ///< SunDisc: unit direction to the disc centre; SkyBin: bin centre
  double half_angle_rad = 0;  ///< SunDisc: angular radius (0 < a <= pi); SkyBin: 0
  double solid_angle_sr = 0;  ///< SkyBin: PatchBasis::solid_angle_sr; SunDisc: 2 pi (1 - cos a)
};

class SourceSet {
 public:
  /// Every bin of `basis` (ground bin 0 first), in RADIANCE row order: source i = bin i.
  static SourceSet sky_bins(const sky::PatchBasis& basis);
  /// No sources yet (add sun discs).
  SourceSet() = default;

  /// Append a disc of angular radius `half_angle_rad` centred on `direction` (toward the
  /// source; normalised here); returns its index. Throws std::invalid_argument for a zero or
  /// non-finite direction or a radius outside (0, pi].
  std::size_t add_sun_disc(const Vec3& direction, double half_angle_rad);

  std::size_t size() const { return m_sources.size(); }
  const DistantSource& operator[](std::size_t i) const { return m_sources[i]; }
  const std::vector<DistantSource>& sources() const { return m_sources; }
  /// The basis of the sky bins (only meaningful when has_basis(): sets built with sky_bins).
  bool has_basis() const { return m_has_basis; }
  const sky::PatchBasis& basis() const { return m_basis; }

  /// A direction (unit) toward source `i`, uniform in its solid angle, from u1, u2 in
  /// [0, 1); the map is area preserving, so stratifying (u1, u2) stratifies the solid angle
  /// (see the header comment). Throws std::out_of_range for a bad index.
  Vec3 sample_direction(std::size_t i, double u1, double u2) const;
  /// True if `direction` (non-zero, toward the sky) lies in source i: the basis puts it in
  /// bin i (PatchBasis::find_bin, RADIANCE's rule), or its angle to the disc centre is at
  /// most the disc's radius. Throws std::out_of_range for a bad index.
  bool contains(std::size_t i, const Vec3& direction) const;
  /// The first source that contains `direction` (non-zero, toward the sky), or -1: for the
  /// bins of a basis, the bin PatchBasis::find_bin gives; otherwise a scan of the discs.
  int find(const Vec3& direction) const;

 private:
  std::vector<DistantSource> m_sources;
  sky::PatchBasis m_basis = sky::PatchBasis::tregenza();
  bool m_has_basis = false;
};

}  // namespace dayphoton::engine
