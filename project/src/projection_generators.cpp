// Plates attached to a wall at one edge: light shelves, overhangs and fins
// (docs/daylight-systems.md). All three are the same plate: an edge on the wall line at
// position q0 (a height for shelves and overhangs, a position along the wall for fins), a
// depth measured along the plate from the wall to its free edge, and an angle that turns
// the free edge toward +q (sigma = +1) or -q (sigma = -1). Within the plane across the
// plate, with q along the wall and w the wall normal (s = +1 outside, -1 inside):
//
//   along   d = (sigma sin a, s cos a)          free edge B = A + depth d
//   normal  n = (sigma cos a, -s sigma sin a)   the face toward +sigma q (a shelf's top)
//
// A thin plate (thickness 0) is the one two-sided polygon A-B with A = (q0, 0) on the wall
// line, its normal n (a shelf's polygon faces up). A slab is the closed quadrilateral A, B, B - t n, D with A = (q0, s g) and D on the
// same wall-parallel line (w = s g) at q0 - sigma t / cos a, so its wall-side face is
// parallel to the wall, g = WallStandoff_m from it (a face in the wall plane would
// coincide with the wall or the glazing). A shelf's tilt raises its free edge for tilt > 0
// (sigma = +1 with q = height); a fin's angle turns its free edge toward the window's
// centre line.
#include <cmath>

#include "dayphoton/core/units.h"
#include "system_generators.h"

namespace dayphoton::project::detail {

namespace {

struct Plate {
  double q0 = 0, sigma = 1, s = 1, angle_rad = 0, depth_m = 0, thickness_m = 0;
};

/// Normal of the plate's face toward +sigma q (a shelf's top), in (q, w).
P2 plate_normal(const Plate& p) {
  return {p.sigma * std::cos(p.angle_rad), -p.s * p.sigma * std::sin(p.angle_rad)};
}

/// The plate's profile in (q, w): 2 points (thin) or the 4 corners of the slab, the first
/// edge being the face toward +sigma q.
std::vector<P2> plate_profile(const Plate& p) {
  const P2 along{p.sigma * std::sin(p.angle_rad), p.s * std::cos(p.angle_rad)};
  if (p.thickness_m == 0) return {P2{p.q0, 0}, P2{p.q0, 0} + along * p.depth_m};
  const P2 normal = plate_normal(p);
  const P2 a{p.q0, p.s * WallStandoff_m};
  const P2 b = a + along * p.depth_m;
  const P2 c = b - normal * p.thickness_m;
  const P2 d{p.q0 - p.sigma * p.thickness_m / std::cos(p.angle_rad), p.s * WallStandoff_m};
  return {a, b, c, d};
}

/// (q, w) -> the profile plane's (x, y): shelves and overhangs use (w, v) with q = v.
std::vector<P2> as_wv(std::vector<P2> qw) {
  for (P2& p : qw) p = {p.y, p.x};
  return qw;
}
P2 as_wv(P2 qw) { return {qw.y, qw.x}; }

/// Build one plate: thin strip (its normal `top_normal`, in the plane's profile
/// coordinates) or slab (top face `top`, other faces `rest`).
void add_plate(const MountedBuild& b, const ProfilePlane& plane, const std::vector<P2>& profile,
               P2 top_normal, double c0, double c1, int top, int rest, const std::string& name) {
  if (profile.size() == 2) {
    add_strip(plane, profile, c0, c1, top, name, b.spec.location, b.out);
    b.out.back().vertices = facing(std::move(b.out.back().vertices), plane.direction(top_normal));
  } else {
    add_prism(plane, profile, c0, c1, {top, rest, rest, rest}, rest, name, b.spec.location, b.out);
  }
}

bool check_materials(const MountedBuild& b, double thickness_m, int top, int rest,
                     const std::string& part) {
  if (top < 0 || rest < 0) return false;
  if (thickness_m > 0) return true;  // a closed slab may be a dielectric (a glass shelf)
  return b.check_not_dielectric("material", top, "a thin " + part);
}

}  // namespace

bool generate_light_shelf(const MountedBuild& b, const LightShelfSpec& p) {
  const int top = b.material("material", p.material);
  const int rest = p.underside_material.empty() ? top
                                                : b.material("underside_material", p.underside_material);
  if (!check_materials(b, p.thickness_m, top, rest, "shelf")) return false;
  const Plate plate{p.height_m, 1.0, b.side_sign(), deg_to_rad(p.tilt_deg), p.depth_m, p.thickness_m};
  add_plate(b, b.wv_plane(), as_wv(plate_profile(plate)), as_wv(plate_normal(plate)),
            -p.extension_m, b.frame.width_m + p.extension_m, top, rest, b.spec.name);
  return true;
}

bool generate_overhang(const MountedBuild& b, const OverhangSpec& p) {
  const int mat = b.material("material", p.material);
  if (!check_materials(b, p.thickness_m, mat, mat, "overhang")) return false;
  const double height = p.height_m ? *p.height_m : b.frame.head_m;
  const Plate plate{height, 1.0, 1.0, deg_to_rad(p.tilt_deg), p.depth_m, p.thickness_m};
  add_plate(b, b.wv_plane(), as_wv(plate_profile(plate)), as_wv(plate_normal(plate)),
            -p.extension_m, b.frame.width_m + p.extension_m, mat, mat, b.spec.name);
  return true;
}

bool generate_fins(const MountedBuild& b, const FinsSpec& p) {
  const int mat = b.material("material", p.material);
  if (!check_materials(b, p.thickness_m, mat, mat, "fin")) return false;
  const double a = deg_to_rad(p.angle_deg);
  const double v0 = b.frame.sill_m - p.extension_m, v1 = b.frame.head_m + p.extension_m;
  if (p.left) {
    // Left jamb (seen from outside) at u = 0: the fin turns toward +u.
    const Plate plate{-p.offset_m, 1.0, 1.0, a, p.depth_m, p.thickness_m};
    add_plate(b, b.uw_plane(), plate_profile(plate), plate_normal(plate), v0, v1, mat, mat,
              b.spec.name + ".left");
  }
  if (p.right) {
    const Plate plate{b.frame.width_m + p.offset_m, -1.0, 1.0, a, p.depth_m, p.thickness_m};
    add_plate(b, b.uw_plane(), plate_profile(plate), plate_normal(plate), v0, v1, mat, mat,
              b.spec.name + ".right");
  }
  return true;
}

}  // namespace dayphoton::project::detail
