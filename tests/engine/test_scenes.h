// Scene descriptions built in C++ for the engine tests and the ray benchmark:
// an axis-aligned (optionally rotated and moved) box room with inward normals, a single
// square, and the reference office (../shared/refdata/scenes/office.rad: 6 x 8 x 3 m, a
// 4 x 1.5 m window in the south wall y = 0, all normals into the room).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"

namespace dayphoton::engine::test {

inline SourceLocation test_location(int line) { return SourceLocation{"test.yaml", line, 3}; }

inline int add_material(SceneDescription& d, const std::string& name, MaterialType type,
                        double reflectance) {
  MaterialSpec m;
  m.name = name;
  m.type = type;
  m.reflectance = {reflectance, reflectance, reflectance};
  if (type == MaterialType::Glass) m.transmittance = {0.6, 0.6, 0.6};
  d.materials.push_back(m);
  return static_cast<int>(d.materials.size()) - 1;
}

inline void add_surface(SceneDescription& d, const std::string& name, int material,
                        std::vector<Vec3> vertices, bool port = false) {
  Surface s;
  s.name = name;
  s.material = material;
  s.vertices = std::move(vertices);
  s.port = port;
  s.location = test_location(static_cast<int>(d.surfaces.size()) + 10);
  d.surfaces.push_back(std::move(s));
}

/// Box room [0,sx] x [0,sy] x [0,sz] with inward normals, rotated by `rotation_rad` about +Z
/// (counter-clockwise seen from above) and then moved by `offset`. Surfaces in the order
/// floor (+z), ceiling (-z), x=0 (+x), x=sx (-x), y=0 (+y), y=sy (-y) before the rotation.
inline SceneDescription box_room(Vec3 size = {1, 1, 1}, double rotation_rad = 0,
                                 Vec3 offset = {0, 0, 0}) {
  SceneDescription d;
  const int m = add_material(d, "grey", MaterialType::Lambertian, 0.5);
  const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  auto P = [&](double x, double y, double z) {
    x *= size.x;
    y *= size.y;
    z *= size.z;
    return Vec3{c * x - s * y, s * x + c * y, z} + offset;
  };
  add_surface(d, "floor", m, {P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)});
  add_surface(d, "ceiling", m, {P(0, 0, 1), P(0, 1, 1), P(1, 1, 1), P(1, 0, 1)});
  add_surface(d, "wall_x0", m, {P(0, 0, 0), P(0, 1, 0), P(0, 1, 1), P(0, 0, 1)});
  add_surface(d, "wall_x1", m, {P(1, 0, 0), P(1, 0, 1), P(1, 1, 1), P(1, 1, 0)});
  add_surface(d, "wall_y0", m, {P(0, 0, 0), P(0, 0, 1), P(1, 0, 1), P(1, 0, 0)});
  add_surface(d, "wall_y1", m, {P(0, 1, 0), P(1, 1, 0), P(1, 1, 1), P(0, 1, 1)});
  return d;
}

/// Rectangle in the plane y = `y`, x in [x0, x1], z in [z0, z1].
inline std::vector<Vec3> rect_at_y(double y, double x0, double x1, double z0, double z1) {
  return {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
}

/// A closed room x [-3, 3], y [-3, 2], z [-1, 3] of material `walls` with the digest's window
/// (y = 2, x [-1, 1], z [0.5, 1.5], facing +y) of material `window` cut into its north wall.
inline void add_window_room(SceneDescription& d, int walls, int window, bool window_is_port = true) {
  add_surface(d, "floor", walls, {{-3, -3, -1}, {3, -3, -1}, {3, 2, -1}, {-3, 2, -1}});
  add_surface(d, "ceiling", walls, {{-3, -3, 3}, {-3, 2, 3}, {3, 2, 3}, {3, -3, 3}});
  add_surface(d, "west", walls, {{-3, -3, -1}, {-3, 2, -1}, {-3, 2, 3}, {-3, -3, 3}});
  add_surface(d, "east", walls, {{3, -3, -1}, {3, -3, 3}, {3, 2, 3}, {3, 2, -1}});
  add_surface(d, "south", walls, rect_at_y(-3, -3, 3, -1, 3));
  add_surface(d, "north_sill", walls, rect_at_y(2, -3, 3, -1, 0.5));
  add_surface(d, "north_head", walls, rect_at_y(2, -3, 3, 1.5, 3));
  add_surface(d, "north_jamb_w", walls, rect_at_y(2, -3, -1, 0.5, 1.5));
  add_surface(d, "north_jamb_e", walls, rect_at_y(2, 1, 3, 0.5, 1.5));
  add_surface(d, "window", window, rect_at_y(2, -1, 1, 0.5, 1.5), window_is_port);
}

/// The square [-1,1]^2 at z = 0, normal +z (counter-clockwise seen from above).
inline SceneDescription single_square() {
  SceneDescription d;
  const int m = add_material(d, "grey", MaterialType::Lambertian, 0.5);
  add_surface(d, "square", m, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  return d;
}

/// Index of the window surface in office_room().
constexpr int OfficeWindowSurface = 9;

/// The reference office, polygon for polygon as in ../shared/refdata/scenes/office.rad.
inline SceneDescription office_room() {
  SceneDescription d;
  const int floor = add_material(d, "floor_mat", MaterialType::Lambertian, 0.2);
  const int wall = add_material(d, "wall_mat", MaterialType::Lambertian, 0.5);
  const int ceiling = add_material(d, "ceiling_mat", MaterialType::Lambertian, 0.7);
  const int glass = add_material(d, "glass_mat", MaterialType::Glass, 0.0);
  add_surface(d, "floor", floor, {{0, 0, 0}, {6, 0, 0}, {6, 8, 0}, {0, 8, 0}});
  add_surface(d, "ceiling", ceiling, {{0, 0, 3}, {0, 8, 3}, {6, 8, 3}, {6, 0, 3}});
  add_surface(d, "wall_west", wall, {{0, 0, 0}, {0, 8, 0}, {0, 8, 3}, {0, 0, 3}});
  add_surface(d, "wall_east", wall, {{6, 0, 0}, {6, 0, 3}, {6, 8, 3}, {6, 8, 0}});
  add_surface(d, "wall_north", wall, {{0, 8, 0}, {6, 8, 0}, {6, 8, 3}, {0, 8, 3}});
  add_surface(d, "wall_south_sill", wall, {{0, 0, 0}, {0, 0, 0.9}, {6, 0, 0.9}, {6, 0, 0}});
  add_surface(d, "wall_south_head", wall, {{0, 0, 2.4}, {0, 0, 3}, {6, 0, 3}, {6, 0, 2.4}});
  add_surface(d, "wall_south_jamb_w", wall, {{0, 0, 0.9}, {0, 0, 2.4}, {1, 0, 2.4}, {1, 0, 0.9}});
  add_surface(d, "wall_south_jamb_e", wall, {{5, 0, 0.9}, {5, 0, 2.4}, {6, 0, 2.4}, {6, 0, 0.9}});
  add_surface(d, "window", glass, {{1, 0, 0.9}, {1, 0, 2.4}, {5, 0, 2.4}, {5, 0, 0.9}},
              /*port=*/true);
  return d;
}

}  // namespace dayphoton::engine::test
