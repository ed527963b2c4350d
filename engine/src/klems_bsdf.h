// KlemsBsdf: scattering by a Klems BSDF matrix (core/klems_bsdf_data.h; docs/materials.md
// "Measured BSDF (Klems)"), in the engine's direction conventions (material.h).
//
// Light arriving along propagation direction d in incoming patch i (of the side it arrives
// on) leaves in outgoing patch j, transmitted or reflected, with probability
//
//   P(j | i) = f(i, j) Lambda_j / A(i),   A(i) = sum_j (T(i, j) + R(i, j)) Lambda_j,
//
// and uniformly in projected solid angle inside patch j (KlemsBasis::sample), so its
// density per steradian is p(o) = P(j | i) |cos o| / Lambda_j = f(i, j) |cos o| / A(i) and
// every sample weighs f |cos o| / p = A(i), the directional albedo (absorbed: 1 - A(i)).
// eval() is the piecewise-constant f(i, j); there is no delta component, so
// straight_transmittance() of a BSDF material is 0 (its direct light reaches sensors as
// photons, docs/direct-component.md).
//
// Frame: z along the surface normal n, y along `up` projected onto the surface, x = y x z
// (RADIANCE's SDcompXform). Light with dot(d, n) > 0 comes from the side n points away from:
// WINDOW's front (the Front matrices); dot(d, n) < 0 is back incidence; dot(d, n) == 0
// scatters nothing.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "dayphoton/core/klems_bsdf_data.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

class KlemsBsdf {
 public:
  /// `up` need not be unit or perpendicular to the surfaces; where it is parallel to a
  /// surface's normal the frame is undefined (Scene::build refuses such a surface).
  KlemsBsdf(std::shared_ptr<const KlemsBsdfData> data, const Vec3& up);

  struct Sample {
    Vec3 direction;
    double weight = 0;  ///< A(i), the same for every sample of that incoming patch
    bool transmitted = false;
  };
  /// Sample the outgoing direction for `incoming` at a surface of normal `normal`; nothing
  /// when the incoming patch scatters nothing (or at exactly grazing incidence).
  std::optional<Sample> sample(const Vec3& incoming, const Vec3& normal, double u_patch, double u1,
                               double u2) const;
  double eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const;
  double pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const;
  double albedo(const Vec3& incoming, const Vec3& normal) const;
  /// The transmitted part of albedo(): sum_j T(i, j) Lambda_j of the side hit.
  double transmittance(const Vec3& incoming, const Vec3& normal) const;

  const KlemsBsdfData& data() const { return *m_data; }

  /// True if `up` defines a frame on a surface of this normal (not parallel to it).
  static bool frame_defined(const Vec3& up, const Vec3& normal);

 private:
  /// Side (0 front, 1 back) and incoming patch of a propagation direction; side -1 if grazing.
  int side_of(const Vec3& local_incoming) const;

  std::shared_ptr<const KlemsBsdfData> m_data;
  Vec3 m_up;
  int m_n = 0;
  /// Per side and incoming patch: cumulative P over 2n outgoing events (transmitted patches
  /// 0..n-1, reflected n..2n-1), unnormalised (the last entry is A(i)).
  std::vector<double> m_cumulative[2];
  std::vector<double> m_lambda;
};

}  // namespace dayphoton::engine
