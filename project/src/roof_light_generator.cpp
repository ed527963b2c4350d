// Roof lights (docs/daylight-systems.md, "Roof lights"): rectangular openings in a room's
// ceiling, glazed either flush with the ceiling or at the top of a light well.
//
// Geometry, room coordinates (x from the room's west wall, y from its south wall), with z_c
// the ceiling height and d the well depth: the opening is [x0, x1] x [y0, y1] at z_c
// (offset_x / offset_y to the near edges, or centred), cut out of the ceiling by the room
// generator. With d > 0 four rectangles rise from the opening's edges to z_c + d, normals
// toward the well's axis, in the well material (default the ceiling's); the well is as
// wide as the opening, so ceiling, well and glazing meet edge to edge with no gap. The
// glazing fills the top of the well (the opening itself when d = 0), normal down into the
// room, and is the photon port (port_emission.h: a port's normal points into the room).
//
// Checks, each located at the offending key: sizes positive, offsets and depth >= 0, the
// opening inside the ceiling (within 1e-6 m, snapped to its edges), apart from the room's
// other roof lights and from the light-pipe openings (their bounding boxes: the ceiling is
// split around them), a glazing that lets light in (glass, opening or translucent: a
// port's own material scatters the photon first), no dielectric (thin surfaces are not
// solids).
//
// Surface names: "<room>.<roof light>" (the glazing) and "<room>.<roof light>.well_<side>"
// with side south (min y), north, east or west (max/min x) of the well.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "geometry_generators.h"
#include "system_geometry.h"

namespace dayphoton::project::detail {

namespace {

constexpr double SnapTolerance_m = 1e-6;

std::string span(double a, double b) { return format_number(a) + " to " + format_number(b) + " m"; }

/// The opening of one roof light, or nothing after reporting why it cannot be built.
std::optional<CeilingRect> opening_of(const RoomSpec& room, const RoofLightSpec& l, const std::string& what,
                                      Diagnostics& diag) {
  const double sx = room.size_m.x, sy = room.size_m.y;
  for (const auto& [key, value] : {std::pair{"width", l.width_m}, std::pair{"length", l.length_m}})
    if (!std::isfinite(value) || value <= 0) {
      report(diag, l.location_of(key), what + ": " + key + " must be positive, got " + format_number(value));
      return std::nullopt;
    }
  for (const auto& [key, value] : {std::pair{"offset_x", l.offset_x_m}, std::pair{"offset_y", l.offset_y_m}})
    if (value && (!std::isfinite(*value) || *value < 0)) {
      report(diag, l.location_of(key), what + ": " + key + " must be >= 0, got " + format_number(*value));
      return std::nullopt;
    }
  if (!std::isfinite(l.well_depth_m) || l.well_depth_m < 0) {
    report(diag, l.location_of("well_depth"),
           what + ": well_depth must be >= 0, got " + format_number(l.well_depth_m));
    return std::nullopt;
  }
  CeilingRect r;
  r.x0 = l.offset_x_m ? *l.offset_x_m : 0.5 * (sx - l.width_m);
  r.x1 = r.x0 + l.width_m;
  r.y0 = l.offset_y_m ? *l.offset_y_m : 0.5 * (sy - l.length_m);
  r.y1 = r.y0 + l.length_m;
  const bool x_fits = r.x0 >= -SnapTolerance_m && r.x1 <= sx + SnapTolerance_m;
  const bool y_fits = r.y0 >= -SnapTolerance_m && r.y1 <= sy + SnapTolerance_m;
  if (!x_fits || !y_fits) {
    const char* key = !x_fits ? (l.offset_x_m ? "offset_x" : "width") : (l.offset_y_m ? "offset_y" : "length");
    report(diag, l.location_of(key),
           what + " does not fit in the ceiling (" + format_number(sx) + " x " + format_number(sy) +
               " m): it spans x " + span(r.x0, r.x1) + " and y " + span(r.y0, r.y1) + " from the room's corner");
    return std::nullopt;
  }
  // Snap to the ceiling's edges so no sliver of ceiling is left.
  r.x0 = std::max(0.0, r.x0);
  r.x1 = std::min(sx, r.x1);
  r.y0 = std::max(0.0, r.y0);
  r.y1 = std::min(sy, r.y1);
  return r;
}

bool overlap(const CeilingRect& a, const CeilingRect& b) {
  return std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > SnapTolerance_m &&
         std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > SnapTolerance_m;
}

/// The bounding box of a light-pipe opening, in room coordinates.
CeilingRect bounding_box(const std::vector<Vec3>& hole, const Vec3& origin) {
  CeilingRect b{hole[0].x - origin.x, hole[0].x - origin.x, hole[0].y - origin.y, hole[0].y - origin.y};
  for (const Vec3& p : hole) {
    b.x0 = std::min(b.x0, p.x - origin.x);
    b.x1 = std::max(b.x1, p.x - origin.x);
    b.y0 = std::min(b.y0, p.y - origin.y);
    b.y1 = std::max(b.y1, p.y - origin.y);
  }
  return b;
}

/// The position key to blame for an overlap: an offset if one was written.
std::string position_key(const RoofLightSpec& l) { return l.offset_x_m ? "offset_x" : l.offset_y_m ? "offset_y" : "name"; }

}  // namespace

std::vector<CeilingRect> generate_roof_lights(const RoomSpec& room, const RoomCutouts& cutouts,
                                              MaterialLookup& materials, Diagnostics& diag,
                                              std::vector<Surface>& out) {
  std::vector<CeilingRect> openings;
  std::vector<const RoofLightSpec*> placed;
  const Vec3 o = room.origin;
  const double z_c = o.z + room.size_m.z;
  for (const RoofLightSpec& l : room.roof_lights) {
    const std::string what = "roof light '" + l.name + "' of room '" + room.name + "'";
    const std::optional<CeilingRect> r = opening_of(room, l, what, diag);
    if (!r) continue;
    bool apart = true;
    for (std::size_t k = 0; k < openings.size() && apart; ++k)
      if (overlap(*r, openings[k])) {
        const SourceLocation& other = placed[k]->location;
        report(diag, l.location_of(position_key(l)),
               what + " overlaps roof light '" + placed[k]->name + "'" +
                   (other.known() ? " (defined at " + other.to_string() + ")" : ""));
        apart = false;
      }
    for (std::size_t k = 0; k < cutouts.ceiling_holes.size() && apart; ++k)
      if (overlap(*r, bounding_box(cutouts.ceiling_holes[k], o))) {
        const std::string owner =
            k < cutouts.ceiling_hole_owners.size() ? cutouts.ceiling_hole_owners[k] : "a light pipe";
        report(diag, l.location_of(position_key(l)), what + " overlaps the ceiling opening of " + owner);
        apart = false;
      }
    if (!apart) continue;

    const int glazing = materials.resolve(l.material, l.location_of("material"), what);
    const bool own_well_material = !l.well_material.empty();
    const int well = materials.resolve(own_well_material ? l.well_material : room.ceiling_material,
                                       own_well_material ? l.location_of("well_material") : room.location,
                                       "the light well of " + what);
    if (glazing < 0 || well < 0) continue;
    const MaterialType gt = materials.spec(glazing).type;
    if (gt != MaterialType::Glass && gt != MaterialType::Opening && gt != MaterialType::Translucent) {
      report(diag, l.location_of("material"),
             what + ": the glazing is the photon port and must let light in (glass, opening or translucent), but '" +
                 l.material + "' is " + material_type_name(gt));
      continue;
    }
    if (materials.spec(well).type == MaterialType::Dielectric) {
      report(diag, own_well_material ? l.location_of("well_material") : room.location,
             what + " cannot use the dielectric '" + materials.spec(well).name +
                 "' for its light well (a dielectric is the surface of a closed solid)");
      continue;
    }

    openings.push_back(*r);
    placed.push_back(&l);
    const double z_t = z_c + l.well_depth_m;
    const double x0 = o.x + r->x0, x1 = o.x + r->x1, y0 = o.y + r->y0, y1 = o.y + r->y1;
    const std::string base = room.name + "." + l.name;
    out.push_back({base, glazing,
                   facing({{x0, y0, z_t}, {x1, y0, z_t}, {x1, y1, z_t}, {x0, y1, z_t}}, {0, 0, -1}), true,
                   l.location});
    if (l.well_depth_m <= 0) continue;
    struct Side {
      const char* name;
      Vec3 a, b, inward;
    };
    const Side sides[4] = {{"south", {x0, y0, 0}, {x1, y0, 0}, {0, 1, 0}},
                           {"north", {x0, y1, 0}, {x1, y1, 0}, {0, -1, 0}},
                           {"east", {x1, y0, 0}, {x1, y1, 0}, {-1, 0, 0}},
                           {"west", {x0, y0, 0}, {x0, y1, 0}, {1, 0, 0}}};
    for (const Side& side : sides) {
      const Vec3 a0{side.a.x, side.a.y, z_c}, b0{side.b.x, side.b.y, z_c};
      const Vec3 a1{side.a.x, side.a.y, z_t}, b1{side.b.x, side.b.y, z_t};
      out.push_back({base + ".well_" + side.name, well, facing({a0, b0, b1, a1}, side.inward), false, l.location});
    }
  }
  return openings;
}

}  // namespace dayphoton::project::detail
