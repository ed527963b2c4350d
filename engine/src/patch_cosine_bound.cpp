// max_cosine_over_patch: see patch_cosine_bound.h for the derivation.
#include "dayphoton/engine/patch_cosine_bound.h"

#include <algorithm>
#include <cmath>

#include "dayphoton/core/units.h"

namespace dayphoton::engine {

double max_cosine_over_patch(const Vec3& m, double z0, double z1, double a0, double a1) {
  // Largest G = H cos(az - az_m) over [a0, a1].
  const double h = std::hypot(m.x, m.y);
  double g = 0;
  if (h > 0) {
    const double az_m = std::atan2(m.x, m.y);
    // The first az_m + 2 pi k at or after a0: inside the range means G = H.
    const double first = az_m + 2 * Pi * std::ceil((a0 - az_m) / (2 * Pi));
    if (a1 - a0 >= 2 * Pi || first <= a1)
      g = h;
    else
      g = h * std::max(std::cos(a0 - az_m), std::cos(a1 - az_m));
  }
  // Largest m_z z + G sqrt(1 - z^2) over z in [z0, z1].
  auto value = [&](double z) { return m.z * z + g * std::sqrt(std::max(0.0, 1 - z * z)); };
  double best = std::max(value(z0), value(z1));
  const double r = std::hypot(m.z, g);
  if (r > 0 && g >= 0) {
    // alt* = atan2(m_z, G) lies in [-pi/2, pi/2] (the altitudes) only when G >= 0; otherwise
    // the band holds no maximum of the sinusoid and an edge is largest.
    const double z_star = m.z / r;
    if (z_star >= z0 && z_star <= z1) best = std::max(best, r);
  }
  return best;
}

}  // namespace dayphoton::engine
