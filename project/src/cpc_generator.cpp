// Compound parabolic concentrators (docs/daylight-systems.md; seeds/000 section 4.2.2;
// W. T. Welford and R. Winston, "High Collection Nonimaging Optics", 1989, chapter 4):
// `count` two-dimensional CPC troughs stacked over a window, each a pair of faceted
// parabolic walls extruded across the window's width.
//
// Profile of one CPC with acceptance half angle theta and exit half width a' (axis +y,
// exit aperture at y = 0, entrance at y = L): the right wall is the parabola whose focus
// is the exit's LEFT edge F = (-a', 0) and whose axis is tilted by theta from the CPC
// axis, so that the extreme rays entering at theta are reflected to F. In polar form about
// F, with psi the angle from the parabola's axis e = (-sin theta, cos theta),
//     r(psi) = 2 a' (1 + sin theta) / (1 - cos psi),
//     P(psi) = F + r(psi) (sin(psi - theta), cos(psi - theta)),
// from psi = pi/2 + theta (P = (a', 0), the exit's right edge) to psi = 2 theta, where the
// wall is parallel to the axis: P = (a, L) with a = a' / sin theta and
// L = (a + a') cot theta (the untruncated CPC). The left wall is the mirror image. Facets
// join the points at equal steps of psi.
//
// Stacking: the troughs are turned by `tilt` (entrance raised toward the sky) about their
// centres and spaced by the height of their turned profile, so that neighbours touch but
// do not overlap (at tilt 0 the entrances, 2a wide, tile the covered height); a is chosen
// so that `count` troughs fill the covered heights. The entrance faces outside; the trough
// nearest the wall is `offset` from the wall plane.
//
// Kinds: `reflective` troughs are the two walls as open strips of the (mirror or metal)
// material, exit and entrance open (a conventional CPC concentrating accepted light onto
// the exit). `dielectric` troughs are closed solids of the dielectric (walls and entrance
// refract or totally reflect) whose exit face is the opaque `exit_material` (seeds/000:
// the sun-shading CPC reflects accepted sunlight back out from its coated exit and
// transmits and fans out light from outside the acceptance range).
#include <algorithm>
#include <cmath>

#include "dayphoton/core/units.h"
#include "system_generators.h"

namespace dayphoton::project::detail {

std::vector<P2> cpc_right_wall(double theta, double exit_half_m, int facets) {
  const double a1 = exit_half_m;
  const double p = 2 * a1 * (1 + std::sin(theta));
  std::vector<P2> wall;
  const double psi0 = 0.5 * Pi + theta, psi1 = 2 * theta;
  for (int k = 0; k <= facets; ++k) {
    const double psi = psi0 + (psi1 - psi0) * k / facets;
    const double r = p / (1 - std::cos(psi));
    wall.push_back({-a1 + r * std::sin(psi - theta), r * std::cos(psi - theta)});
  }
  // Exact end points (the formula gives them up to rounding).
  wall.front() = {a1, 0};
  wall.back() = {a1 / std::sin(theta), (a1 / std::sin(theta) + a1) / std::tan(theta)};
  return wall;
}

bool generate_cpc(const MountedBuild& b, const CpcSpec& p) {
  const int mat = b.material("material", p.material);
  if (mat < 0) return false;
  int exit_mat = -1;
  if (p.dielectric) {
    if (!b.check_dielectric("material", mat)) return false;
    exit_mat = b.material("exit_material", p.exit_material);
    if (exit_mat < 0) return false;
    const MaterialType t = b.materials.spec(exit_mat).type;
    if (t != MaterialType::Lambertian && t != MaterialType::Metal && t != MaterialType::Mirror) {
      b.error("exit_material", "needs an opaque exit coating (lambertian, plastic, metal or mirror), but '" +
                                   b.materials.spec(exit_mat).name + "' is " + material_type_as_written(b.materials.spec(exit_mat)));
      return false;
    }
  } else if (!b.check_not_dielectric("material", mat, "the walls of a reflective CPC")) {
    return false;
  }
  double v0 = 0, v1 = 0;
  if (!b.covered_heights(p.bottom_m, p.top_m, v0, v1)) return false;
  const double theta = deg_to_rad(p.acceptance_angle_deg), tilt = deg_to_rad(p.tilt_deg);

  // Unit profile (entrance half width a = 1), turned about its centre: (x, y) -> (w, v).
  const std::vector<P2> unit_right = cpc_right_wall(theta, std::sin(theta), p.facets);
  const double half_length = 0.5 * unit_right.back().y;
  auto turned = [&](P2 q) {  // axis y -> (cos tilt, sin tilt) in (w, v), x -> (-sin, cos)
    const double y = q.y - half_length;
    return P2{y * std::cos(tilt) - q.x * std::sin(tilt), y * std::sin(tilt) + q.x * std::cos(tilt)};
  };
  double wmin = 1e300, wmax = -1e300, vmin = 1e300, vmax = -1e300;
  for (const P2& q : unit_right)
    for (const P2& r : {turned(q), turned({-q.x, q.y})}) {
      wmin = std::min(wmin, r.x);
      wmax = std::max(wmax, r.x);
      vmin = std::min(vmin, r.y);
      vmax = std::max(vmax, r.y);
    }
  const double pitch = (v1 - v0) / p.count;
  const double a = pitch / (vmax - vmin);  // entrance half width that fills the height
  const double w_centre = b.spec.mount.side == MountSide::Interior ? -p.offset_m - a * wmax
                                                                    : p.offset_m - a * wmin;
  const double u1 = b.frame.width_m;
  for (int k = 0; k < p.count; ++k) {
    const double v_centre = v0 + (k + 0.5) * pitch - a * 0.5 * (vmax + vmin);
    auto place = [&](P2 q) {
      const P2 r = turned(q) * a;
      return P2{w_centre + r.x, v_centre + r.y};
    };
    std::vector<P2> right, left;
    for (const P2& q : unit_right) {
      right.push_back(place(q));
      left.push_back(place({-q.x, q.y}));
    }
    const std::string name = b.spec.name + ".trough" + std::to_string(k + 1);
    if (!p.dielectric) {
      add_strip(b.wv_plane(), right, 0, u1, mat, name + ".right", b.spec.location, b.out);
      add_strip(b.wv_plane(), left, 0, u1, mat, name + ".left", b.spec.location, b.out);
      continue;
    }
    // Right wall exit -> entrance, left wall entrance -> exit; the last edge is the exit.
    std::vector<P2> solid = right;
    solid.insert(solid.end(), left.rbegin(), left.rend());
    std::vector<int> edges(solid.size(), mat);
    edges.back() = exit_mat;
    add_prism(b.wv_plane(), solid, 0, u1, edges, mat, name, b.spec.location, b.out);
  }
  return true;
}

}  // namespace dayphoton::project::detail
