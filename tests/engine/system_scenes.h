// Scenes with daylight systems for tests/engine/daylight_systems_test.cpp, built by hand
// from the geometry that docs/daylight-systems.md describes. The engine tests cannot link
// the project library, so these are written independently of project/src/*_generator.cpp;
// tests/project/systems_test.cpp checks that the generators produce the same surfaces for
// the same parameters, which ties the engine's acceptance tests to the generators.
//
// Frame: a room [0, sx] x [0, sy] x [0, sz] with its window in the south wall y = 0, so
// the window frame's u is +x, w (outward) is -y and v is z (window_frame.h).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/polygon.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/units.h"
#include "test_scenes.h"

namespace dayphoton::engine::test {

inline int add_spec(SceneDescription& d, const MaterialSpec& m) {
  d.materials.push_back(m);
  return static_cast<int>(d.materials.size()) - 1;
}

inline MaterialSpec material_of(const std::string& name, MaterialType type) {
  MaterialSpec m;
  m.name = name;
  m.type = type;
  return m;
}

inline MaterialSpec grey(const std::string& name, MaterialType type, double reflectance) {
  MaterialSpec m = material_of(name, type);
  m.reflectance = {reflectance, reflectance, reflectance};
  if (type == MaterialType::Metal) m.specularity = 1;
  return m;
}

inline MaterialSpec glass_of(const std::string& name, double normal_transmittance) {
  MaterialSpec m = material_of(name, MaterialType::Glass);
  m.transmittance = {normal_transmittance, normal_transmittance, normal_transmittance};
  return m;
}

inline MaterialSpec dielectric_of(const std::string& name, double index) {
  MaterialSpec m = material_of(name, MaterialType::Dielectric);
  m.refractive_index = index;
  m.transmittance = {1, 1, 1};
  return m;
}

/// `polygon` wound so that its normal points along `normal`.
inline std::vector<Vec3> wound(std::vector<Vec3> polygon, const Vec3& normal) {
  if (dot(polygon_normal(polygon), normal) < 0) std::reverse(polygon.begin() + 1, polygon.end());
  return polygon;
}

inline void add_facing(SceneDescription& d, const std::string& name, int material,
                       std::vector<Vec3> polygon, const Vec3& normal, bool port = false) {
  add_surface(d, name, material, wound(std::move(polygon), normal), port);
}

/// Axis-aligned rectangle in the plane z = const (x0..x1, y0..y1).
inline std::vector<Vec3> rect_z(double x0, double x1, double y0, double y1, double z) {
  return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}
/// ... in the plane y = const (x0..x1, z0..z1).
inline std::vector<Vec3> rect_y(double x0, double x1, double z0, double z1, double y) {
  return {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
}
/// ... in the plane x = const (y0..y1, z0..z1).
inline std::vector<Vec3> rect_x(double y0, double y1, double z0, double z1, double x) {
  return {{x, y0, z0}, {x, y1, z0}, {x, y1, z1}, {x, y0, z1}};
}

struct SouthWindow {
  double x0, x1, z0, z1;
  int material;
  bool port = true;
};

/// Closed box room, normals inward; optionally a window in the south wall and an
/// axis-aligned rectangular opening [hx0, hx1] x [hy0, hy1] in the ceiling.
inline void add_room(SceneDescription& d, const Vec3& size, int floor, int ceiling, int walls,
                     const std::optional<SouthWindow>& window,
                     const std::optional<std::array<double, 4>>& ceiling_hole = std::nullopt) {
  const double sx = size.x, sy = size.y, sz = size.z;
  add_facing(d, "floor", floor, rect_z(0, sx, 0, sy, 0), {0, 0, 1});
  if (!ceiling_hole) {
    add_facing(d, "ceiling", ceiling, rect_z(0, sx, 0, sy, sz), {0, 0, -1});
  } else {
    const auto [hx0, hx1, hy0, hy1] = *ceiling_hole;
    add_facing(d, "ceiling.w", ceiling, rect_z(0, hx0, 0, sy, sz), {0, 0, -1});
    add_facing(d, "ceiling.e", ceiling, rect_z(hx1, sx, 0, sy, sz), {0, 0, -1});
    add_facing(d, "ceiling.s", ceiling, rect_z(hx0, hx1, 0, hy0, sz), {0, 0, -1});
    add_facing(d, "ceiling.n", ceiling, rect_z(hx0, hx1, hy1, sy, sz), {0, 0, -1});
  }
  add_facing(d, "wall_west", walls, rect_x(0, sy, 0, sz, 0), {1, 0, 0});
  add_facing(d, "wall_east", walls, rect_x(0, sy, 0, sz, sx), {-1, 0, 0});
  add_facing(d, "wall_north", walls, rect_y(0, sx, 0, sz, sy), {0, -1, 0});
  const Vec3 in{0, 1, 0};
  if (!window) {
    add_facing(d, "wall_south", walls, rect_y(0, sx, 0, sz, 0), in);
    return;
  }
  const SouthWindow& w = *window;
  if (w.z0 > 0) add_facing(d, "wall_south.sill", walls, rect_y(0, sx, 0, w.z0, 0), in);
  if (w.z1 < sz) add_facing(d, "wall_south.head", walls, rect_y(0, sx, w.z1, sz, 0), in);
  if (w.x0 > 0) add_facing(d, "wall_south.left", walls, rect_y(0, w.x0, w.z0, w.z1, 0), in);
  if (w.x1 < sx) add_facing(d, "wall_south.right", walls, rect_y(w.x1, sx, w.z0, w.z1, 0), in);
  add_facing(d, "window", w.material, rect_y(w.x0, w.x1, w.z0, w.z1, 0), in, w.port);
}

/// Closed axis-aligned box lo..hi with outward normals; the top face (+z) gets `top`, the
/// others `rest`.
inline void add_box(SceneDescription& d, const std::string& name, const Vec3& lo, const Vec3& hi,
                    int top, int rest) {
  add_facing(d, name + ".top", top, rect_z(lo.x, hi.x, lo.y, hi.y, hi.z), {0, 0, 1});
  add_facing(d, name + ".bottom", rest, rect_z(lo.x, hi.x, lo.y, hi.y, lo.z), {0, 0, -1});
  add_facing(d, name + ".ymin", rest, rect_y(lo.x, hi.x, lo.z, hi.z, lo.y), {0, -1, 0});
  add_facing(d, name + ".ymax", rest, rect_y(lo.x, hi.x, lo.z, hi.z, hi.y), {0, 1, 0});
  add_facing(d, name + ".xmin", rest, rect_x(lo.y, hi.y, lo.z, hi.z, lo.x), {-1, 0, 0});
  add_facing(d, name + ".xmax", rest, rect_x(lo.y, hi.y, lo.z, hi.z, hi.x), {1, 0, 0});
}

/// Port enclosure of a south window: a box x0..x1, -depth..0, z0..z1 of `opening` ports,
/// open toward the wall, normals into the box (docs/daylight-systems.md, "Ports").
inline void add_enclosure(SceneDescription& d, int opening, double x0, double x1, double z0,
                          double z1, double depth) {
  add_facing(d, "enclosure.front", opening, rect_y(x0, x1, z0, z1, -depth), {0, 1, 0}, true);
  add_facing(d, "enclosure.top", opening, rect_z(x0, x1, -depth, 0, z1), {0, 0, -1}, true);
  add_facing(d, "enclosure.bottom", opening, rect_z(x0, x1, -depth, 0, z0), {0, 0, 1}, true);
  add_facing(d, "enclosure.left", opening, rect_x(-depth, 0, z0, z1, x0), {1, 0, 0}, true);
  add_facing(d, "enclosure.right", opening, rect_x(-depth, 0, z0, z1, x1), {-1, 0, 0}, true);
}

/// Regular polygon of a light pipe: `sides` vertices on the circle of radius r around
/// (cx, cy) at height z, counter-clockwise from above, the first at angle pi / sides.
inline std::vector<Vec3> pipe_polygon(double cx, double cy, double r, int sides, double z) {
  std::vector<Vec3> p;
  for (int k = 0; k < sides; ++k) {
    const double phi = Pi * (2.0 * k + 1.0) / sides;
    p.push_back({cx + r * std::cos(phi), cy + r * std::sin(phi), z});
  }
  return p;
}

/// A light pipe standing on z = z_bottom: tube (inward normals), a diffuser across the bottom
/// (normal down; skipped if diffuser < 0) and a collector on top: flat (dome_rings = 0) or a
/// faceted hemisphere; collector facets are ports with normals into the pipe.
inline void add_light_pipe(SceneDescription& d, double cx, double cy, double diameter,
                           double z_bottom, double length, int sides, int tube, int diffuser,
                           int collector, int dome_rings) {
  const double r = 0.5 * diameter, z_top = z_bottom + length;
  const std::vector<Vec3> lo = pipe_polygon(cx, cy, r, sides, z_bottom);
  const std::vector<Vec3> hi = pipe_polygon(cx, cy, r, sides, z_top);
  if (diffuser >= 0) add_facing(d, "pipe.diffuser", diffuser, lo, {0, 0, -1});
  for (int k = 0; k < sides; ++k) {
    const int j = (k + 1) % sides;
    const Vec3 mid = (lo[k] + lo[j]) * 0.5;
    add_facing(d, "pipe.tube." + std::to_string(k + 1), tube, {lo[k], lo[j], hi[j], hi[k]},
               Vec3{cx, cy, z_bottom} - mid);
  }
  if (dome_rings == 0) {
    add_facing(d, "pipe.collector", collector, hi, {0, 0, -1}, true);
    return;
  }
  const Vec3 centre{cx, cy, z_top};
  auto ring = [&](int i, int k) {
    const double e = 0.5 * Pi * i / dome_rings;
    const double phi = Pi * (2.0 * (k % sides) + 1.0) / sides;
    return Vec3{cx + r * std::cos(e) * std::cos(phi), cy + r * std::cos(e) * std::sin(phi),
                z_top + r * std::sin(e)};
  };
  for (int i = 0; i < dome_rings; ++i)
    for (int k = 0; k < sides; ++k) {
      std::vector<Vec3> f{ring(i, k), ring(i, k + 1)};
      if (i + 1 < dome_rings) {
        f.push_back(ring(i + 1, k + 1));
        f.push_back(ring(i + 1, k));
      } else {
        f.push_back(centre + Vec3{0, 0, r});
      }
      Vec3 mid{0, 0, 0};
      for (const Vec3& p : f) mid = mid + p * (1.0 / double(f.size()));
      add_facing(d, "pipe.dome." + std::to_string(i + 1) + "." + std::to_string(k + 1), collector,
                 f, centre - mid, true);
    }
}

/// Lamella panel (Y-glass) inside a south window: strips of `material` spanning x0..x1,
/// depth d = y - offset in [0, T] from the face toward the window, heights z0..z1; lamellae
/// `spacing` apart at mid-depth, centred, inclined by beta (room-side edge lower), each an
/// air gap `gap` wide perpendicular to it; top and bottom edges horizontal.
inline void add_lamella_panel(SceneDescription& d, int material, double x0, double x1, double z0,
                              double z1, double offset, double thickness, double spacing,
                              double beta_rad, double gap) {
  const int strips = static_cast<int>(std::floor((z1 - z0) / spacing + 1e-9));
  const int lamellae = strips - 1;
  const double mid = 0.5 * (z0 + z1), gv = gap / std::cos(beta_rad), slope = std::tan(beta_rad);
  auto lamella = [&](int j, double depth) {
    return mid + (j - 0.5 * (lamellae + 1)) * spacing - (depth - 0.5 * thickness) * slope;
  };
  for (int k = 0; k <= lamellae; ++k) {
    auto lo = [&](double depth) { return k == 0 ? z0 : lamella(k, depth) + 0.5 * gv; };
    auto hi = [&](double depth) { return k == lamellae ? z1 : lamella(k + 1, depth) - 0.5 * gv; };
    const double ya = offset, yb = offset + thickness;
    const std::string name = "panel.strip" + std::to_string(k + 1);
    // Profile in (y, z), counter-clockwise seen from +x: outward normals below.
    const std::array<std::array<double, 2>, 4> q = {{{ya, lo(0)}, {yb, lo(thickness)},
                                                     {yb, hi(thickness)}, {ya, hi(0)}}};
    const Vec3 centre{0.5 * (x0 + x1), 0.5 * (ya + yb),
                      0.25 * (lo(0) + lo(thickness) + hi(0) + hi(thickness))};
    for (int e = 0; e < 4; ++e) {
      const auto& a = q[e];
      const auto& b = q[(e + 1) % 4];
      std::vector<Vec3> face{{x0, a[0], a[1]}, {x0, b[0], b[1]}, {x1, b[0], b[1]}, {x1, a[0], a[1]}};
      Vec3 fc{0, 0, 0};
      for (const Vec3& p : face) fc = fc + p * 0.25;
      add_facing(d, name + ".side" + std::to_string(e), material, face, fc - centre);
    }
    std::vector<Vec3> cap0, cap1;
    for (const auto& a : q) {
      cap0.push_back({x0, a[0], a[1]});
      cap1.push_back({x1, a[0], a[1]});
    }
    add_facing(d, name + ".cap0", material, cap0, {-1, 0, 0});
    add_facing(d, name + ".cap1", material, cap1, {1, 0, 0});
  }
}

}  // namespace dayphoton::engine::test
