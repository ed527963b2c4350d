// Venetian blinds (docs/daylight-systems.md): horizontal slats in front of a window.
//
// One slat, in its own frame (x along the chord from the room-side edge, -c/2, to the
// window-side edge, +c/2; y up at angle 0): a circular arc of chord c and rise h (the
// crown) through (+-c/2, 0) and (0, h), radius R = (c^2/4 + h^2) / (2h), cut into `facets`
// facets of equal angle (x = R sin psi, y = R cos psi - (R - h), |psi| <= asin(c / 2R));
// a flat slat (h = 0) is one facet. The slat is turned by the slat angle alpha so that the
// window-side edge goes DOWN for alpha > 0:
//   (x, y) -> (x cos alpha + y sin alpha, -x sin alpha + y cos alpha),
// and placed with its axis (the chord's midpoint) at distance `offset` from the wall plane
// on the system's side, x pointing toward the window. At alpha = 90 the slats hang
// vertically with the convex side toward the window (closed); alpha = 0 is horizontal
// (open); alpha < 0 tilts the window-side edge up.
//
// Axes: n = floor((top - bottom) / spacing) slats (at least one), spacing apart, centred
// on the covered heights. Each slat spans the window's width plus `extension` on both
// sides and is two-sided (the material applies to both faces; a slat has no thickness).
// Slats longer than the spacing overlap when nearly closed, as real slats do.
#include <cmath>

#include "dayphoton/core/units.h"
#include "system_generators.h"

namespace dayphoton::project::detail {

bool generate_blinds(const MountedBuild& b, const BlindsSpec& p) {
  const int mat = b.material("material", p.material);
  if (mat < 0 || !b.check_not_dielectric("material", mat, "slats")) return false;
  double v0 = 0, v1 = 0;
  if (!b.covered_heights(p.bottom_m, p.top_m, v0, v1)) return false;
  const double c = p.slat_width_m, h = p.crown_m;
  if (h > 0.5 * c) {
    b.error("crown", "has a crown of " + format_number(h) + " m, more than half its slat width (" +
                         format_number(c) + " m): the slat would be more than a half circle");
    return false;
  }
  std::vector<P2> slat;
  if (h == 0) {
    slat = {{-0.5 * c, 0}, {0.5 * c, 0}};
  } else {
    const double radius = (0.25 * c * c + h * h) / (2 * h);
    const double half = std::asin(std::min(1.0, 0.5 * c / radius));
    for (int k = 0; k <= p.facets; ++k) {
      const double psi = -half + 2 * half * k / p.facets;
      slat.push_back({radius * std::sin(psi), radius * std::cos(psi) - (radius - h)});
    }
  }
  const double alpha = deg_to_rad(p.angle_deg);
  const double offset = p.offset_m ? *p.offset_m : 0.5 * c + 0.02;
  // x toward the window: +w inside the room (the window is at w = 0 > axis), -w outside.
  const double toward_window = -b.side_sign();
  const double axis_w = b.side_sign() * offset;
  const int n = std::max(1, static_cast<int>(std::floor((v1 - v0) / p.spacing_m + 1e-9)));
  const double first = 0.5 * (v0 + v1) - 0.5 * (n - 1) * p.spacing_m;
  for (int k = 0; k < n; ++k) {
    std::vector<P2> profile;
    for (const P2& q : slat) {
      const double x = q.x * std::cos(alpha) + q.y * std::sin(alpha);
      const double y = -q.x * std::sin(alpha) + q.y * std::cos(alpha);
      profile.push_back({axis_w + toward_window * x, first + k * p.spacing_m + y});
    }
    add_strip(b.wv_plane(), profile, -p.extension_m, b.frame.width_m + p.extension_m, mat,
              b.spec.name + ".slat" + std::to_string(k + 1), b.spec.location, b.out);
  }
  return true;
}

}  // namespace dayphoton::project::detail
