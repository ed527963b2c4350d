// Shirley-Chiu concentric mapping between the unit square [0,1)^2 and the unit disc: the
// angle basis "LBNL/Shirley-Chiu" of tensor-tree BSDF files (core/tensor_tree_bsdf_data.h).
// The mapping preserves area (a square region of area a maps to a disc region of area pi a),
// and a unit direction (x, y, +-z) projects onto the disc at (x, y), where area is projected
// solid angle; so a square cell of side s is a set of directions of projected solid angle
// pi s^2.
// Source: P. Shirley, K. Chiu, "A Low Distortion Map Between Disk and Square", Journal of
// Graphics Tools 2(3), 1997, section 3 (the four "pie slice" regions; the phi < -pi/4 wrap
// as corrected in the authors' 2004 note); RADIANCE uses the same regions and orientation
// (G. Ward, src/common/disk2square.c, SDsquare2disk / SDdisk2square).
#pragma once

#include <cmath>

namespace dayphoton {

/// Square point (u, v) in [0,1]^2 -> disc point (x, y), |(x, y)| <= 1.
inline void shirley_chiu_square_to_disc(double u, double v, double& x, double& y) {
  constexpr double QuarterPi = 0.78539816339744830962;
  const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
  double r = 0, phi = 0;
  if (a > -b) {
    if (a > b) {  // region 1: |a| > |b|
      r = a;
      phi = QuarterPi * (b / a);
    } else {  // region 2: |b| >= |a|
      r = b;
      phi = QuarterPi * (2.0 - a / b);
    }
  } else {
    if (a < b) {  // region 3
      r = -a;
      phi = QuarterPi * (4.0 + b / a);
    } else {  // region 4 (a == b == 0 included)
      r = -b;
      phi = b != 0.0 ? QuarterPi * (6.0 - a / b) : 0.0;
    }
  }
  x = r * std::cos(phi);
  y = r * std::sin(phi);
}

/// Disc point (x, y), |(x, y)| <= 1 -> square point (u, v) in [0,1]^2.
inline void shirley_chiu_disc_to_square(double x, double y, double& u, double& v) {
  constexpr double Pi = 3.14159265358979323846, QuarterPi = Pi / 4;
  const double r = std::sqrt(x * x + y * y);
  double phi = std::atan2(y, x);
  if (phi < -QuarterPi) phi += 2 * Pi;  // [-pi/4, 7pi/4)
  double a = 0, b = 0;
  if (phi < QuarterPi) {
    a = r;
    b = phi * a / QuarterPi;
  } else if (phi < 3 * QuarterPi) {
    b = r;
    a = -(phi - Pi / 2) * b / QuarterPi;
  } else if (phi < 5 * QuarterPi) {
    a = -r;
    b = (phi - Pi) * a / QuarterPi;
  } else {
    b = -r;
    a = -(phi - 3 * Pi / 2) * b / QuarterPi;
  }
  u = (a + 1) * 0.5;
  v = (b + 1) * 0.5;
}

}  // namespace dayphoton
