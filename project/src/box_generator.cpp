// Box generator: an axis-aligned box origin + [0, size.x] x [0, size.y] x [0, size.z],
// rotated about the vertical axis through its origin corner by rotation_deg
// (counter-clockwise seen from above for positive angles, the right-hand rule about +Z),
// as six quadrilaterals with OUTWARD normals (a solid obstruction, a shelf, a column).
// Surface names: "<box>.bottom", ".top", ".south", ".north", ".west", ".east" (the face
// names refer to the unrotated box).
#include "dayphoton/core/diagnostics.h"
#include <cmath>

#include "dayphoton/core/units.h"
#include "geometry_generators.h"

namespace dayphoton::project::detail {

void generate_box(const BoxSpec& box, MaterialLookup& materials, Diagnostics& diag,
                  std::vector<Surface>& out) {
  const std::string what = "box '" + box.name + "'";
  if (!is_finite(box.origin) || !std::isfinite(box.rotation_deg)) {
    report(diag, box.location, what + ": origin and rotation must be finite");
    return;
  }
  const Vec3 s = box.size_m;
  if (!(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z) && s.x > 0 && s.y > 0 && s.z > 0)) {
    report(diag, box.location,
           what + ": every size must be positive, got " + format_number(s.x) + " x " +
               format_number(s.y) + " x " + format_number(s.z) + " m");
    return;
  }
  const int mat = materials.resolve(box.material, box.location, what);
  const double a = deg_to_rad(box.rotation_deg);
  const double c = std::cos(a), sn = std::sin(a);
  // Corner (i, j, k) in {0,1}^3 of the box, rotated about the origin corner then placed.
  auto corner = [&](int i, int j, int k) {
    const double x = i * s.x, y = j * s.y, z = k * s.z;
    return box.origin + Vec3{x * c - y * sn, x * sn + y * c, z};
  };
  struct Face {
    const char* name;
    int v[4][3];
  };
  // Each face wound counter-clockwise seen from outside.
  static const Face faces[6] = {
      {"bottom", {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}},  // -z
      {"top", {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}},     // +z
      {"south", {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}},   // -y
      {"north", {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}},   // +y
      {"west", {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}},    // -x
      {"east", {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}},    // +x
  };
  for (const Face& f : faces) {
    Surface surface;
    surface.name = box.name + "." + f.name;
    surface.material = mat;
    for (const auto& v : f.v) surface.vertices.push_back(corner(v[0], v[1], v[2]));
    surface.solid_face = true;
    surface.outdoor_scatterer = box.outdoor;
    surface.location = box.location;
    out.push_back(std::move(surface));
  }
}

}  // namespace dayphoton::project::detail
