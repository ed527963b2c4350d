// BsdfFrame: an orthonormal frame (tangent, bitangent, normal) around a unit normal, used by
// the scattering models to turn directions sampled about +z into world directions.
//
// Why this construction: it is branch-light and stays orthonormal to rounding error for every
// unit normal, including (0, 0, -1), unlike the classic cross-product-with-an-axis methods.
// Source: T. Duff, J. Burgess, P. Christensen, C. Hery, A. Kensler, M. Liani, R. Villemin,
// "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017 (listing 3).
#pragma once

#include <cmath>

#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

struct BsdfFrame {
  Vec3 tangent, bitangent, normal;

  explicit BsdfFrame(const Vec3& unit_normal) : normal(unit_normal) {
    const double sign = std::copysign(1.0, unit_normal.z);
    const double a = -1.0 / (sign + unit_normal.z);
    const double b = unit_normal.x * unit_normal.y * a;
    tangent = {1.0 + sign * unit_normal.x * unit_normal.x * a, sign * b, -sign * unit_normal.x};
    bitangent = {b, sign + unit_normal.y * unit_normal.y * a, -unit_normal.y};
  }

  /// World direction of the local vector (x along tangent, y along bitangent, z along normal).
  Vec3 to_world(const Vec3& local) const {
    return tangent * local.x + bitangent * local.y + normal * local.z;
  }
};

/// The frame of a measured BSDF (Klems or tensor tree; docs/materials.md): z along the
/// surface normal, y along `up` projected onto the surface, x = y x z (RADIANCE's
/// SDcompXform). Where `up` is within MinUpSine of the normal the frame is undefined (the
/// scene refuses such a surface); any orthonormal frame then keeps the numbers finite.
struct UpFrame {
  /// |up x n| below this (up within 0.06 degrees of the normal) leaves the frame undefined.
  static constexpr double MinUpSine = 1e-3;
  Vec3 x, y, z;

  UpFrame(const Vec3& up, const Vec3& normal) {
    z = normalize(normal);
    const Vec3 across = cross(up, z);
    if (length(across) > MinUpSine * length(up)) {
      x = normalize(across);
      y = cross(z, x);
    } else {
      const BsdfFrame b(z);
      x = b.tangent;
      y = b.bitangent;
    }
  }
  Vec3 to_local(const Vec3& v) const { return {dot(v, x), dot(v, y), dot(v, z)}; }
  Vec3 to_world(const Vec3& v) const { return x * v.x + y * v.y + z * v.z; }
};

}  // namespace dayphoton::engine
