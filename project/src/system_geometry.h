// Building blocks of the daylight-system generators (docs/daylight-systems.md): 2-D
// profiles placed in a plane of the model and extruded along the third axis, either as
// closed prisms (solids: a dielectric needs outward normals, since its front side is the
// outside) or as open strips (thin two-sided reflectors such as slats and mirror walls).
// Profiles are lists of P2 points; a ProfilePlane maps them to model space.
#pragma once

#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project::detail {

/// A point (or direction) of a 2-D profile.
struct P2 {
  double x = 0, y = 0;
};

inline P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
inline P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
inline P2 operator*(P2 a, double s) { return {a.x * s, a.y * s}; }

/// `p` rotated counter-clockwise by `angle_rad` about the profile origin.
P2 rotate(P2 p, double angle_rad);

/// Twice the signed area of a profile (> 0 counter-clockwise in (x, y)).
double signed_area2(const std::vector<P2>& profile);

/// Profiles in model space: at(p, c) = origin + ax p.x + ay p.y + ac c, with orthonormal
/// axes; c is the extrusion coordinate.
struct ProfilePlane {
  Vec3 origin, ax, ay, ac;
  Vec3 at(P2 p, double c) const { return origin + ax * p.x + ay * p.y + ac * c; }
  Vec3 direction(P2 d) const { return ax * d.x + ay * d.y; }
};

/// `polygon` with its winding turned, if needed, so that its normal points along `normal`.
std::vector<Vec3> facing(std::vector<Vec3> polygon, const Vec3& normal);

/// A closed prism: the simple polygon `profile` (either winding) extruded from c0 to c1.
/// Side face i (profile edge i -> i + 1) gets edge_materials[i], the two end caps
/// cap_material; every normal points out of the solid. Faces are named
/// "<name>.side<i>", "<name>.cap0", "<name>.cap1".
void add_prism(const ProfilePlane& plane, const std::vector<P2>& profile, double c0, double c1,
               const std::vector<int>& edge_materials, int cap_material, const std::string& name,
               const SourceLocation& location, std::vector<Surface>& out);

/// An open strip: each segment of `polyline` extruded from c0 to c1 as one quadrilateral
/// of `material` ("<name>.<i>"), normal on the segment's left (for two-sided materials the
/// side does not matter).
void add_strip(const ProfilePlane& plane, const std::vector<P2>& polyline, double c0, double c1,
               int material, const std::string& name, const SourceLocation& location,
               std::vector<Surface>& out);

}  // namespace dayphoton::project::detail
