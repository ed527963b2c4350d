// Light pipe (docs/daylight-systems.md; seeds/000 section 4.2.3): a vertical tube with a
// specular lining that carries daylight from a roof collector down through a room's
// ceiling to a diffuser.
//
// Geometry, model coordinates, with z_c the room's ceiling height: the tube is a regular
// polygon of `sides` vertices on the circle of diameter `diameter` around (x, y)
// (light_pipe_polygon), extruded from z_c up to z_c + length as one quadrilateral per side
// with normals toward the axis. The room's ceiling gets the polygon as an opening
// (RoomCutouts), the diffuser fills it exactly (same vertices, normal down into the room),
// so the ceiling, tube and diffuser meet edge to edge with no gap. The collector closes the
// top and is the photon port (the tube is the only way in):
//   - flat: the polygon at z_c + length, normal down;
//   - dome: a faceted hemisphere on the polygon's circumcircle, `dome_rings` rings of
//     `sides` facets (isosceles trapezoids, planar because their corners are symmetric
//     about the facet's mid-azimuth plane) and a cap of triangles, normals toward the
//     centre. A convex dome's facets do not overlap as seen from any direction, so each
//     ray's flux enters once (port_emission.h).
// Checks: the polygon lies inside the ceiling (1 mm from its edges), the collector material
// lets light in (glass, opening or translucent: a port's own material scatters the photon
// first), and no part is a dielectric (thin surfaces are not solids).
#include <cmath>

#include "dayphoton/core/units.h"
#include "system_generators.h"

namespace dayphoton::project::detail {

std::vector<Vec3> light_pipe_polygon(const LightPipeSpec& p, double z_m) {
  std::vector<Vec3> polygon;
  const double r = 0.5 * p.diameter_m;
  for (int k = 0; k < p.sides; ++k) {
    const double phi = Pi / p.sides + 2 * Pi * k / p.sides;
    polygon.push_back({p.x_m + r * std::cos(phi), p.y_m + r * std::sin(phi), z_m});
  }
  return polygon;
}

bool generate_light_pipe(const SystemSpec& spec, const LightPipeSpec& p, const RoomSpec& room,
                         MaterialLookup& materials, Diagnostics& diag, std::vector<Surface>& out,
                         RoomCutouts& cutouts) {
  const std::string what = "light_pipe '" + spec.name + "'";
  auto material = [&](const char* key, const std::string& name) {
    const int m = materials.resolve(name, spec.location_of(key), what);
    if (m >= 0 && materials.spec(m).type == MaterialType::Dielectric) {
      report(diag, spec.location_of(key),
             what + " cannot use the dielectric '" + name + "' as its " + key +
                 " (a dielectric is the surface of a closed solid)");
      return -1;
    }
    return m;
  };
  const int tube = material("tube_material", p.tube_material);
  const int diffuser = material("diffuser_material", p.diffuser_material);
  const int collector = material("collector_material", p.collector_material);
  if (tube < 0 || diffuser < 0 || collector < 0) return false;
  const MaterialType ct = materials.spec(collector).type;
  if (ct != MaterialType::Glass && ct != MaterialType::Glazing && ct != MaterialType::Opening &&
      ct != MaterialType::Translucent) {
    report(diag, spec.location_of("collector_material"),
           what + ": the collector is the photon port and must let light in (glass, glazing, "
                  "opening or translucent), but '" + p.collector_material + "' is " + material_type_as_written(materials.spec(collector)));
    return false;
  }
  const double r = 0.5 * p.diameter_m, margin = 1e-3;
  const Vec3 o = room.origin, s = room.size_m;
  if (p.x_m - r < o.x + margin || p.x_m + r > o.x + s.x - margin || p.y_m - r < o.y + margin ||
      p.y_m + r > o.y + s.y - margin) {
    report(diag, spec.location_of("x"),
           what + " (diameter " + format_number(p.diameter_m) + " m at x = " + format_number(p.x_m) +
               ", y = " + format_number(p.y_m) + ") does not fit in the ceiling of room '" +
               room.name + "' (x " + format_coordinate(o.x) + " to " + format_coordinate(o.x + s.x) + ", y " +
               format_coordinate(o.y) + " to " + format_coordinate(o.y + s.y) + ")");
    return false;
  }
  const double z_c = o.z + s.z, z_t = z_c + p.length_m;
  const std::vector<Vec3> bottom = light_pipe_polygon(p, z_c), top = light_pipe_polygon(p, z_t);
  const Vec3 axis_bottom{p.x_m, p.y_m, z_c};
  auto add = [&](const std::string& name, int mat, std::vector<Vec3> v, const Vec3& normal, bool port) {
    Surface surface;
    surface.name = spec.name + "." + name;
    surface.material = mat;
    surface.vertices = facing(std::move(v), normal);
    surface.port = port;
    // The collector, flat or a dome of facets, stands for the opening the pipe cuts in the
    // roof: its daylight enters through a horizontal opening (EN 17037's rule for them).
    if (port) surface.opening_normal = {0, 0, 1};
    surface.location = spec.location;
    out.push_back(std::move(surface));
  };
  cutouts.ceiling_holes.push_back(bottom);
  cutouts.ceiling_hole_owners.push_back(what);
  add("diffuser", diffuser, bottom, {0, 0, -1}, false);
  const int n = p.sides;
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    const Vec3 mid = (bottom[k] + bottom[j]) * 0.5;
    add("tube." + std::to_string(k + 1), tube, {bottom[k], bottom[j], top[j], top[k]},
        axis_bottom - mid, false);
  }
  if (!p.dome) {
    add("collector", collector, top, {0, 0, -1}, true);
    return true;
  }
  // Dome: ring i at elevation angle e_i = i (pi/2) / rings; the top ring is the apex.
  const Vec3 centre{p.x_m, p.y_m, z_t};
  auto ring_point = [&](int i, int k) {
    const double e = 0.5 * Pi * i / p.dome_rings;
    const Vec3 d = top[static_cast<std::size_t>(k % n)] - centre;
    return centre + d * std::cos(e) + Vec3{0, 0, r * std::sin(e)};
  };
  for (int i = 0; i < p.dome_rings; ++i)
    for (int k = 0; k < n; ++k) {
      std::vector<Vec3> facet{ring_point(i, k), ring_point(i, k + 1)};
      if (i + 1 < p.dome_rings) {
        facet.push_back(ring_point(i + 1, k + 1));
        facet.push_back(ring_point(i + 1, k));
      } else {
        facet.push_back(centre + Vec3{0, 0, r});
      }
      Vec3 mid{0, 0, 0};
      for (const Vec3& v : facet) mid = mid + v;
      mid = mid * (1.0 / double(facet.size()));
      add("collector." + std::to_string(i + 1) + "." + std::to_string(k + 1), collector, facet,
          centre - mid, true);
    }
  return true;
}

}  // namespace dayphoton::project::detail
